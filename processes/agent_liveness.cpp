#include "processes/agent_liveness.hpp"

#include <algorithm>
#include <cstdio>

namespace chatsim::processes {

void AgentLiveness::observe(const std::string& node, const std::string& kind, int pid, double period_s, bool stopping,
                            double now_s) {
  nodes_[node] = {kind, pid, now_s, period_s > 0 ? period_s : 0.5, stopping};
}

bool AgentLiveness::alive(const Entry& e, double now_s) const {
  return !e.stopping && now_s - e.last_s <= std::max(min_timeout_s_, missed_beats_ * e.period_s);
}

std::vector<AgentLiveness::Instance> AgentLiveness::snapshot(const std::string& kind, double now_s) const {
  std::vector<Instance> out;
  for (const auto& [name, e] : nodes_)
    if (e.kind == kind && alive(e, now_s)) out.push_back({name, e.pid});
  return out;
}

std::optional<std::string> AgentLiveness::lost(const std::string& kind, const std::vector<Instance>& sent_to,
                                               double now_s) const {
  if (sent_to.empty()) return std::nullopt;  // nothing known to have gone: wait for the deadline
  std::string why;
  for (const auto& i : sent_to) {
    const auto it = nodes_.find(i.node);
    if (it == nodes_.end()) continue;
    const Entry& e = it->second;
    char buf[200];
    if (e.pid != i.pid) {
      std::snprintf(buf, sizeof buf, "'%s' restarted (pid %d, now %d) and lost the request", i.node.c_str(), i.pid, e.pid);
    } else if (e.stopping) {
      std::snprintf(buf, sizeof buf, "'%s' (pid %d) stopped", i.node.c_str(), i.pid);
    } else if (!alive(e, now_s)) {
      std::snprintf(buf, sizeof buf, "'%s' (pid %d) fell silent: no heartbeat for %.1f s", i.node.c_str(), i.pid,
                    now_s - e.last_s);
    } else {
      return std::nullopt;  // one that got the request is still up
    }
    why += (why.empty() ? "" : "; ") + std::string(buf);
  }
  return "the " + kind + " agent failed while answering: " + why;
}

}  // namespace chatsim::processes
