#include "processes/agent_liveness.hpp"

#include <cstdio>

namespace chatsim::processes {

void AgentLiveness::observe(const std::string& node, const std::string& kind, int pid, double period_s, bool stopping,
                            double now_s) {
  monitor_.observe(node, now_s, period_s, stopping);
  nodes_[node] = {kind, pid};
}

std::vector<AgentLiveness::Instance> AgentLiveness::snapshot(const std::string& kind, double now_s) const {
  std::vector<Instance> out;
  for (const auto& [name, id] : nodes_)
    if (id.kind == kind && monitor_.alive(name, now_s)) out.push_back({name, id.pid});
  return out;
}

std::optional<std::string> AgentLiveness::lost(const std::string& kind, const std::vector<Instance>& sent_to,
                                               double now_s) const {
  if (sent_to.empty()) return std::nullopt;  // nothing known to have gone: wait for the deadline
  std::string why;
  for (const auto& i : sent_to) {
    const auto it = nodes_.find(i.node);
    if (it == nodes_.end()) continue;
    char buf[200];
    if (it->second.pid != i.pid) {
      std::snprintf(buf, sizeof buf, "'%s' restarted (pid %d, now %d) and lost the request", i.node.c_str(), i.pid,
                    it->second.pid);
    } else if (monitor_.stopped(i.node)) {
      std::snprintf(buf, sizeof buf, "'%s' (pid %d) stopped", i.node.c_str(), i.pid);
    } else if (!monitor_.alive(i.node, now_s)) {
      std::snprintf(buf, sizeof buf, "'%s' (pid %d) fell silent: no heartbeat for %.1f s", i.node.c_str(), i.pid,
                    now_s - monitor_.last_seen_s(i.node));
    } else {
      return std::nullopt;  // one that got the request is still up
    }
    why += (why.empty() ? "" : "; ") + std::string(buf);
  }
  return "the " + kind + " agent failed while answering: " + why;
}

}  // namespace chatsim::processes
