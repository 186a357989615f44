#pragma once
// Records bus traffic to MCAP and plays it back. The recorder never loses messages silently:
// sequence gaps, failed verifications and its own overflow are counted and stored in the file.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace chatsim::bag {

struct RecordOptions {
  std::string bus;
  std::vector<std::string> topics;   // exact topics; empty with all = every topic
  bool all = false;
  double duration_s = 0;             // 0: until stopped
  std::filesystem::path out;
  bool force = false;                // replace a recording (an MCAP file) already at `out`
  size_t max_queue_bytes = size_t(1) << 30;
  std::atomic<bool>* ready = nullptr;  // set once subscribed (benchmarks wait for it)
};

struct RecordReport {
  uint64_t messages = 0;      // written
  uint64_t bytes = 0;         // message bytes written
  uint64_t lost = 0;          // sequence gaps seen on the bus
  uint64_t invalid = 0;       // dropped by verification
  uint64_t overflow = 0;      // dropped because the writer fell more than max_queue_bytes behind
  double seconds = 0;
  double write_mb_s = 0;      // message bytes per second of writer busy time
  uint64_t file_bytes = 0;
};

// Records until stop is set or duration_s passes. progress(report) is called about once a second.
// Before connecting, `out` is checked: no folder, no file but (with force) an earlier recording,
// and no interrupted recording (`out`.part) to overwrite; OutputDirError otherwise.
RecordReport record(const RecordOptions& options, const std::atomic<bool>& stop,
                    const std::function<void(const RecordReport&)>& progress = {});

struct PlayOptions {
  std::string bus;
  std::filesystem::path file;
  double rate = 1.0;                 // 0: as fast as possible
  std::vector<std::string> topics;   // empty: every flatbuffer channel
  bool loop = false;
};

// Republishes the recording's messages with their original spacing (divided by rate), in
// log-time order, which keeps each topic's order. Headers keep sender and sequence; send
// time and deadline move to now. Returns how many were sent.
uint64_t play(const PlayOptions& options, const std::atomic<bool>& stop);

// Base64 (RFC 4648), for JSON-encoded image messages.
std::string base64(std::string_view bytes);

}  // namespace chatsim::bag
