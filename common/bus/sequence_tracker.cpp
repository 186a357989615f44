#include "common/bus/sequence_tracker.hpp"

namespace chatsim::bus {

SequenceTracker::Observation SequenceTracker::observe(std::string_view sender,
                                                      uint64_t sender_instance,
                                                      std::string_view topic, uint64_t seq) {
  key_.clear();  // reused: no allocation per message once streams are known
  key_.append(sender).push_back('\0');
  key_.append(topic);

  Observation obs;
  auto it = streams_.find(key_);
  if (it == streams_.end()) {  // first message seen: nothing to compare with (late joiner)
    streams_.emplace(key_, Stream{sender_instance, seq});
    return obs;
  }
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
