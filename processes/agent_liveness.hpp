#pragma once
// Which agent processes are up, by kind, from their heartbeats; and whether the ones that
// were up when a request went out are still the same processes. Transport-free: feed it
// heartbeats and the time. The manager uses it to report a dead agent in seconds rather than
// waiting out the request's deadline.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace chatsim::processes {

class AgentLiveness {
 public:
  explicit AgentLiveness(double missed_beats = 3.0, double min_timeout_s = 1.0)
      : missed_beats_(missed_beats), min_timeout_s_(min_timeout_s) {}

  void observe(const std::string& node, const std::string& kind, int pid, double period_s, bool stopping, double now_s);

  struct Instance {
    std::string node;
    int pid = 0;
  };
  // The live instances of a kind now: the ones a request sent now can reach.
  std::vector<Instance> snapshot(const std::string& kind, double now_s) const;
  // Why a request sent to `sent_to` can no longer be answered, if it cannot: every one of
  // them fell silent, said it was stopping, or restarted (a new pid under the same name).
  std::optional<std::string> lost(const std::string& kind, const std::vector<Instance>& sent_to, double now_s) const;

 private:
  struct Entry {
    std::string kind;
    int pid = 0;
    double last_s = 0, period_s = 0.5;
    bool stopping = false;
  };
  bool alive(const Entry& e, double now_s) const;

  double missed_beats_, min_timeout_s_;
  std::map<std::string, Entry> nodes_;
};

}  // namespace chatsim::processes
