#include "common/bus/sequence_tracker.hpp"

namespace chatsim::bus {

SequenceTracker::Observation SequenceTracker::observe(std::string_view sender,
                                                      uint64_t sender_instance,
                                                      std::string_view topic, uint64_t seq) {
  std::string key;
  key.reserve(sender.size() + topic.size() + 1);
  key.append(sender).push_back('\0');
  key.append(topic);

  Observation obs;
  auto [it, inserted] = streams_.try_emplace(std::move(key), Stream{sender_instance, seq});
  if (inserted) return obs;  // first message seen: nothing to compare with (late joiner)
  Stream& s = it->second;
  if (s.instance != sender_instance) {
    obs.restarted = true;
    ++restarts_;
    s = Stream{sender_instance, seq};
    return obs;
  }
  if (seq <= s.last_seq) {
    obs.duplicate = true;
    ++duplicates_;
    return obs;
  }
  obs.missing = seq - s.last_seq - 1;
  gaps_ += obs.missing;
  s.last_seq = seq;
  return obs;
}

}  // namespace chatsim::bus
