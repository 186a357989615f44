#pragma once
// Reads the MCAP files our writer makes (and other single-file MCAPs with zstd or no
// compression): the summary for `bag info`, and every message in log-time order for `bag play`.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "common/bag/mcap_writer.hpp"

namespace chatsim::bag {

struct McapChannel {
  uint16_t id = 0;
  uint16_t schema_id = 0;
  std::string topic, message_encoding, schema_name, schema_encoding;
  std::map<std::string, std::string> metadata;
};

struct McapSummary {
  uint64_t message_count = 0;
  uint64_t start_ns = 0, end_ns = 0;
  uint32_t chunk_count = 0;
  std::map<uint16_t, McapChannel> channels;
  std::map<uint16_t, uint64_t> channel_counts;
  std::map<std::string, std::map<std::string, std::string>> metadata;  // by name
};

struct McapMessage {
  const McapChannel* channel = nullptr;
  uint32_t sequence = 0;
  uint64_t log_time = 0, publish_time = 0;
  std::string_view data;
};

class McapReader {
 public:
  explicit McapReader(const std::filesystem::path& file);  // reads the whole file; throws McapError
  const McapSummary& summary() const { return summary_; }
  // Every message in log-time order (chunks are in order; within a chunk, by log time).
  void for_each(const std::function<void(const McapMessage&)>& f) const;

 private:
  std::string bytes_;
  McapSummary summary_;
  std::vector<std::pair<uint64_t, uint64_t>> chunks_;  // offset, length of each chunk record
  std::filesystem::path file_;
};

}  // namespace chatsim::bag
