#include "common/bag/mcap_writer.hpp"

#include <zlib.h>

#include <algorithm>
#include <functional>
#include <tuple>
#include <zstd.h>

#include "common/bag/mcap_bytes.hpp"

namespace chatsim::bag {
using namespace mcap;

namespace {

uint32_t crc(uint32_t running, std::string_view bytes) {
  return uint32_t(crc32(running, reinterpret_cast<const Bytef*>(bytes.data()), uInt(bytes.size())));
}

std::string record(uint8_t opcode, const std::string& body) {
  std::string r;
  r.reserve(9 + body.size());
  put<uint8_t>(r, opcode);
  put<uint64_t>(r, body.size());
  r += body;
  return r;
}

}  // namespace

// The same records go in the data section and again in the summary.
std::string McapWriter::schema_body(const Schema& s) {
  std::string b;
  put<uint16_t>(b, s.id);
  put_string(b, s.name);
  put_string(b, s.encoding);
  put_string(b, s.data);
  return b;
}

std::string McapWriter::channel_body(const Channel& c) {
  std::string b;
  put<uint16_t>(b, c.id);
  put<uint16_t>(b, c.schema_id);
  put_string(b, c.topic);
  put_string(b, c.encoding);
  put_map(b, c.metadata);
  return b;
}

McapWriter::McapWriter(const std::filesystem::path& file, Options options)
    : out_(file, std::ios::binary | std::ios::trunc), options_(std::move(options)) {
  if (!out_) throw McapError(file.string() + ": cannot open for writing");
  const std::string magic(kMagic, 8);
  out_.write(magic.data(), 8);
  offset_ = 8;
  data_crc_ = crc(0, magic);
  std::string h;
  put_string(h, options_.profile);
  put_string(h, options_.library);
  write_record(kHeader, h);
}

McapWriter::~McapWriter() {
  try {
    close();
  } catch (...) {
  }
}

void McapWriter::write_record(uint8_t opcode, const std::string& body, bool to_data_crc) {
  const std::string r = record(opcode, body);
  out_.write(r.data(), std::streamsize(r.size()));
  if (to_data_crc) data_crc_ = crc(data_crc_, r);
  offset_ += r.size();
}

uint16_t McapWriter::add_schema(const std::string& name, const std::string& encoding, std::string_view data) {
  const uint16_t id = uint16_t(schemas_.size() + 1);
  schemas_.push_back({id, name, encoding, std::string(data)});
  write_record(kSchema, schema_body(schemas_.back()));
  return id;
}

uint16_t McapWriter::add_channel(uint16_t schema_id, const std::string& topic, const std::string& encoding,
                                 const std::map<std::string, std::string>& metadata) {
  const uint16_t id = uint16_t(channels_.size() + 1);
  channels_.push_back({id, schema_id, topic, encoding, metadata});
  write_record(kChannel, channel_body(channels_.back()));
  return id;
}

void McapWriter::write(uint16_t channel, uint32_t sequence, uint64_t log_time, uint64_t publish_time, std::string_view data) {
  if (closed_) throw McapError("write after close");
  chunk_index_[channel].emplace_back(log_time, chunk_.size());
  std::string b;
  put<uint16_t>(b, channel);
  put<uint32_t>(b, sequence);
  put<uint64_t>(b, log_time);
  put<uint64_t>(b, publish_time);
  put<uint8_t>(chunk_, kMessage);
  put<uint64_t>(chunk_, b.size() + data.size());
  chunk_ += b;
  chunk_.append(data);
  chunk_start_ = std::min(chunk_start_, log_time);
  chunk_end_ = std::max(chunk_end_, log_time);
  first_time_ = std::min(first_time_, log_time);
  last_time_ = std::max(last_time_, log_time);
  ++message_count_;
  ++channel_counts_[channel];
  if (chunk_.size() >= options_.chunk_size) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.empty()) return;
  std::string compressed(ZSTD_compressBound(chunk_.size()), '\0');
  const size_t n = ZSTD_compress(compressed.data(), compressed.size(), chunk_.data(), chunk_.size(), options_.zstd_level);
  if (ZSTD_isError(n)) throw McapError(std::string("zstd: ") + ZSTD_getErrorName(n));
  compressed.resize(n);
  std::string b;
  put<uint64_t>(b, chunk_start_);
  put<uint64_t>(b, chunk_end_);
  put<uint64_t>(b, chunk_.size());
  put<uint32_t>(b, crc(0, chunk_));
  put_string(b, "zstd");
  put<uint64_t>(b, compressed.size());
  b += compressed;
  ChunkIndex ci{chunk_start_, chunk_end_, offset_, 0, 0, compressed.size(), chunk_.size(), {}};
  write_record(kChunk, b);
  ci.length = offset_ - ci.offset;
  const uint64_t index_start = offset_;
  for (auto& [channel, entries] : chunk_index_) {
    std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string mi;
    put<uint16_t>(mi, channel);
    put<uint32_t>(mi, uint32_t(entries.size() * 16));
    for (const auto& [t, off] : entries) {
      put<uint64_t>(mi, t);
      put<uint64_t>(mi, off);
    }
    ci.index_offsets[channel] = offset_;
    write_record(kMessageIndex, mi);
  }
  ci.index_length = offset_ - index_start;
  chunk_indexes_.push_back(ci);
  chunk_.clear();
  chunk_index_.clear();
  chunk_start_ = UINT64_MAX;
  chunk_end_ = 0;
}

void McapWriter::add_metadata(const std::string& name, const std::map<std::string, std::string>& values) {
  flush_chunk();  // metadata records live between chunks
  std::string b;
  put_string(b, name);
  put_map(b, values);
  metadata_.emplace_back(name, offset_);
  write_record(kMetadata, b);
  metadata_lengths_.push_back(offset_ - metadata_.back().second);
}

void McapWriter::close() {
  if (closed_) return;
  flush_chunk();
  closed_ = true;
  std::string de;
  put<uint32_t>(de, data_crc_);
  write_record(kDataEnd, de, false);

  // Summary: groups of records, each group's place in the summary offset section.
  const uint64_t summary_start = offset_;
  uint32_t summary_crc = 0;
  std::vector<std::tuple<uint8_t, uint64_t, uint64_t>> groups;
  auto summary_record = [&](uint8_t op, const std::string& body) {
    const std::string r = record(op, body);
    out_.write(r.data(), std::streamsize(r.size()));
    summary_crc = crc(summary_crc, r);
    offset_ += r.size();
  };
  auto group = [&](uint8_t op, const std::function<void()>& write_group) {
    const uint64_t start = offset_;
    write_group();
    if (offset_ > start) groups.emplace_back(op, start, offset_ - start);
  };
  group(kSchema, [&] {
    for (const auto& s : schemas_) summary_record(kSchema, schema_body(s));
  });
  group(kChannel, [&] {
    for (const auto& c : channels_) summary_record(kChannel, channel_body(c));
  });
  group(kStatistics, [&] {
    std::string b;
    put<uint64_t>(b, message_count_);
    put<uint16_t>(b, uint16_t(schemas_.size()));
    put<uint32_t>(b, uint32_t(channels_.size()));
    put<uint32_t>(b, 0);  // attachments
    put<uint32_t>(b, uint32_t(metadata_.size()));
    put<uint32_t>(b, uint32_t(chunk_indexes_.size()));
    put<uint64_t>(b, message_count_ ? first_time_ : 0);
    put<uint64_t>(b, message_count_ ? last_time_ : 0);
    std::string counts;
    for (const auto& [ch, n] : channel_counts_) {
      put<uint16_t>(counts, ch);
      put<uint64_t>(counts, n);
    }
    put<uint32_t>(b, uint32_t(counts.size()));
    b += counts;
    summary_record(kStatistics, b);
  });
  group(kChunkIndex, [&] {
    for (const auto& ci : chunk_indexes_) {
      std::string b;
      put<uint64_t>(b, ci.start);
      put<uint64_t>(b, ci.end);
      put<uint64_t>(b, ci.offset);
      put<uint64_t>(b, ci.length);
      std::string offsets;
      for (const auto& [ch, off] : ci.index_offsets) {
        put<uint16_t>(offsets, ch);
        put<uint64_t>(offsets, off);
      }
      put<uint32_t>(b, uint32_t(offsets.size()));
      b += offsets;
      put<uint64_t>(b, ci.index_length);
      put_string(b, "zstd");
      put<uint64_t>(b, ci.compressed);
      put<uint64_t>(b, ci.uncompressed);
      summary_record(kChunkIndex, b);
    }
  });
  group(kMetadataIndex, [&] {
    for (size_t i = 0; i < metadata_.size(); ++i) {
      std::string b;
      put<uint64_t>(b, metadata_[i].second);
      put<uint64_t>(b, metadata_lengths_[i]);
      put_string(b, metadata_[i].first);
      summary_record(kMetadataIndex, b);
    }
  });
  const uint64_t summary_offset_start = offset_;
  for (const auto& [op, start, length] : groups) {
    std::string b;
    put<uint8_t>(b, op);
    put<uint64_t>(b, start);
    put<uint64_t>(b, length);
    summary_record(kSummaryOffset, b);
  }
  // Footer: its CRC covers the summary, the offsets and the footer up to the CRC field.
  std::string footer;
  put<uint8_t>(footer, kFooter);
  put<uint64_t>(footer, 8 + 8 + 4);
  put<uint64_t>(footer, summary_start);
  put<uint64_t>(footer, summary_offset_start);
  summary_crc = crc(summary_crc, footer);
  put<uint32_t>(footer, summary_crc);
  footer.append(kMagic, 8);
  out_.write(footer.data(), std::streamsize(footer.size()));
  offset_ += footer.size();
  out_.close();
  if (!out_) throw McapError("writing the MCAP file failed (disk full?)");
}

}  // namespace chatsim::bag
