#pragma once
// Which agent processes are up, by kind, and whether the ones that were up when a request went
// out are still the same processes. Liveness itself is the bus's HeartbeatMonitor; this adds
// each node's kind and pid. Transport-free: feed it heartbeats and the time. The manager and
// `chatsim plan` use it to report a dead agent in seconds rather than at the request's deadline.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/bus/heartbeat_monitor.hpp"

namespace chatsim::processes {

class AgentLiveness {
 public:
  explicit AgentLiveness(double missed_beats = 3.0, double min_timeout_s = 1.0) : monitor_(missed_beats, min_timeout_s) {}

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
  struct Identity {
    std::string kind;
    int pid = 0;
  };
  bus::HeartbeatMonitor monitor_;
  std::map<std::string, Identity> nodes_;
};

}  // namespace chatsim::processes
