#pragma once
// Counts messages lost between a publisher and this receiver from per-(sender, topic)
// sequence numbers. Transport-free so it is unit-tested on its own.
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>

namespace chatsim::bus {

class SequenceTracker {
 public:
  struct Observation {
    uint64_t missing = 0;     // messages skipped before this one
    bool duplicate = false;   // seq not newer than the last one (re-sent or reordered)
    bool restarted = false;   // the publisher process changed (new instance id)
  };

  Observation observe(std::string_view sender, uint64_t sender_instance, std::string_view topic,
                      uint64_t seq);

  uint64_t gaps() const { return gaps_; }
  uint64_t duplicates() const { return duplicates_; }
  uint64_t restarts() const { return restarts_; }

 private:
  struct Stream {
    uint64_t instance = 0;
    uint64_t last_seq = 0;
  };
  std::unordered_map<std::string, Stream> streams_;
  std::string key_;
  uint64_t gaps_ = 0;
  uint64_t duplicates_ = 0;
  uint64_t restarts_ = 0;
};

}  // namespace chatsim::bus
