#pragma once
// A minimal MCAP writer (https://mcap.dev/spec): header, schemas and channels, zstd-compressed
// chunks each followed by its message indexes, data end with the data CRC, and a summary
// section (schemas, channels, statistics, chunk indexes, metadata index) with summary
// offsets and CRC, so indexed readers can seek.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace chatsim::bag {

class McapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class McapWriter {
 public:
  struct Options {
    std::string profile;                 // "" (none)
    std::string library = "chatsim";
    size_t chunk_size = 4 << 20;         // uncompressed bytes per chunk
    int zstd_level = 3;
  };

  McapWriter(const std::filesystem::path& file, Options options);
  ~McapWriter();  // closes if still open

  uint16_t add_schema(const std::string& name, const std::string& encoding, std::string_view data);
  uint16_t add_channel(uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                       const std::map<std::string, std::string>& metadata = {});
  void write(uint16_t channel_id, uint32_t sequence, uint64_t log_time_ns, uint64_t publish_time_ns, std::string_view data);
  void add_metadata(const std::string& name, const std::map<std::string, std::string>& values);
  void close();

  uint64_t messages() const { return message_count_; }
  uint64_t bytes_written() const { return offset_; }

 private:
  struct Schema {
    uint16_t id;
    std::string name, encoding, data;
  };
  struct Channel {
    uint16_t id, schema_id;
    std::string topic, encoding;
    std::map<std::string, std::string> metadata;
  };
  struct ChunkIndex {
    uint64_t start, end, offset, length, index_length, compressed, uncompressed;
    std::map<uint16_t, uint64_t> index_offsets;
  };
  static std::string schema_body(const Schema& s);
  static std::string channel_body(const Channel& c);
  void write_record(uint8_t opcode, const std::string& body, bool to_data_crc = true);
  void flush_chunk();

  std::ofstream out_;
  Options options_;
  uint64_t offset_ = 0;
  uint32_t data_crc_ = 0;
  bool closed_ = false;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  // The open chunk.
  std::string chunk_;
  uint64_t chunk_start_ = UINT64_MAX, chunk_end_ = 0;
  std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> chunk_index_;  // channel -> (time, offset)
  std::vector<ChunkIndex> chunk_indexes_;
  std::vector<std::pair<std::string, uint64_t>> metadata_;  // name, offset of its record
  std::vector<uint64_t> metadata_lengths_;
  uint64_t message_count_ = 0, first_time_ = UINT64_MAX, last_time_ = 0;
  std::map<uint16_t, uint64_t> channel_counts_;
};

}  // namespace chatsim::bag
