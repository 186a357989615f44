#include "common/bag/mcap_reader.hpp"

#include <zstd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "common/bag/mcap_bytes.hpp"

namespace chatsim::bag {
using namespace mcap;

McapReader::McapReader(const std::filesystem::path& file) : file_(file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw McapError(file.string() + ": cannot open");
  std::ostringstream s;
  s << in.rdbuf();
  bytes_ = s.str();
  const std::string magic(kMagic, 8);
  if (bytes_.size() < 8 + 9 + 20 + 8 || bytes_.compare(0, 8, magic) != 0 || bytes_.compare(bytes_.size() - 8, 8, magic) != 0)
    throw McapError(file.string() + ": not an MCAP file (magic bytes missing; was the recording interrupted?)");
  // Walk the data section: the file is small enough to read in full, and walking needs no summary.
  std::map<uint16_t, std::pair<std::string, std::string>> schemas;
  Cursor c{bytes_.data() + 8, bytes_.data() + bytes_.size() - 8};
  try {
    while (c.p < c.end) {
      const uint64_t at = uint64_t(c.p - bytes_.data());
      const uint8_t op = c.get<uint8_t>();
      const uint64_t len = c.get<uint64_t>();
      Cursor r{c.p, c.p + len};
      c.bytes(len);
      if (op == kSchema) {
        const uint16_t id = r.get<uint16_t>();
        std::string name(r.string());
        schemas[id] = {name, std::string(r.string())};
      } else if (op == kChannel) {
        McapChannel ch;
        ch.id = r.get<uint16_t>();
        ch.schema_id = r.get<uint16_t>();
        ch.topic = r.string();
        ch.message_encoding = r.string();
        ch.metadata = r.map();
        if (schemas.count(ch.schema_id)) {
          ch.schema_name = schemas[ch.schema_id].first;
          ch.schema_encoding = schemas[ch.schema_id].second;
        }
        summary_.channels[ch.id] = ch;
      } else if (op == kChunk) {
        chunks_.emplace_back(at, 9 + len);
        const uint64_t start = r.get<uint64_t>(), end = r.get<uint64_t>();
        if (summary_.chunk_count++ == 0 || start < summary_.start_ns) summary_.start_ns = start;
        summary_.end_ns = std::max(summary_.end_ns, end);
      } else if (op == kMetadata) {
        std::string name(r.string());
        summary_.metadata[name] = r.map();
      } else if (op == kDataEnd) {
        break;
      }
    }
  } catch (const std::out_of_range& e) {
    throw McapError(file.string() + ": damaged record (" + e.what() + ")");
  }
  for_each([&](const McapMessage& m) {
    ++summary_.message_count;
    ++summary_.channel_counts[m.channel->id];
  });
}

void McapReader::for_each(const std::function<void(const McapMessage&)>& f) const {
  std::string plain;
  for (const auto& [offset, length] : chunks_) {
    Cursor r{bytes_.data() + offset + 9, bytes_.data() + offset + length};
    r.get<uint64_t>();
    r.get<uint64_t>();
    const uint64_t uncompressed = r.get<uint64_t>();
    r.get<uint32_t>();
    const std::string compression(r.string());
    const uint64_t size = r.get<uint64_t>();
    const std::string_view records = r.bytes(size);
    if (compression == "zstd") {
      plain.resize(uncompressed);
      const size_t n = ZSTD_decompress(plain.data(), plain.size(), records.data(), records.size());
      if (ZSTD_isError(n) || n != uncompressed) throw McapError(file_.string() + ": a chunk does not decompress");
    } else if (compression.empty()) {
      plain.assign(records);
    } else {
      throw McapError(file_.string() + ": chunk compression '" + compression + "' is not supported (zstd or none)");
    }
    std::vector<McapMessage> msgs;
    Cursor c{plain.data(), plain.data() + plain.size()};
    while (c.p < c.end) {
      const uint8_t op = c.get<uint8_t>();
      const uint64_t len = c.get<uint64_t>();
      Cursor m{c.p, c.p + len};
      c.bytes(len);
      if (op != kMessage) continue;
      McapMessage msg;
      const uint16_t ch = m.get<uint16_t>();
      const auto it = summary_.channels.find(ch);
      if (it == summary_.channels.end()) throw McapError(file_.string() + ": a message names an unknown channel");
      msg.channel = &it->second;
      msg.sequence = m.get<uint32_t>();
      msg.log_time = m.get<uint64_t>();
      msg.publish_time = m.get<uint64_t>();
      msg.data = std::string_view(m.p, size_t(m.end - m.p));
      msgs.push_back(msg);
    }
    std::stable_sort(msgs.begin(), msgs.end(), [](const McapMessage& a, const McapMessage& b) { return a.log_time < b.log_time; });
    for (const auto& m : msgs) f(m);
  }
}

}  // namespace chatsim::bag
