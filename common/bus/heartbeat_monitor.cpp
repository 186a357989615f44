#include "common/bus/heartbeat_monitor.hpp"

#include <algorithm>

namespace chatsim::bus {

void HeartbeatMonitor::observe(const std::string& node, double now_s, double period_s,
                               bool stopping) {
  Entry& e = nodes_[node];
  e.last_s = now_s;
  if (period_s > 0) e.period_s = period_s;
  e.stopped = stopping;
}

double HeartbeatMonitor::timeout(const Entry& e) const {
  return std::max(min_timeout_s_, missed_beats_ * e.period_s);
}

bool HeartbeatMonitor::alive(const std::string& node, double now_s) const {
  const auto it = nodes_.find(node);
  if (it == nodes_.end() || it->second.stopped) return false;
  return now_s - it->second.last_s <= timeout(it->second);
}

bool HeartbeatMonitor::stopped(const std::string& node) const {
  const auto it = nodes_.find(node);
  return it != nodes_.end() && it->second.stopped;
}

double HeartbeatMonitor::last_seen_s(const std::string& node) const {
  const auto it = nodes_.find(node);
  return it == nodes_.end() ? -1.0 : it->second.last_s;
}

std::vector<std::string> HeartbeatMonitor::overdue(double now_s) const {
  std::vector<std::string> out;
  for (const auto& [name, e] : nodes_) {
    if (!e.stopped && now_s - e.last_s > timeout(e)) out.push_back(name);
  }
  return out;
}

std::vector<std::string> HeartbeatMonitor::names() const {
  std::vector<std::string> out;
  for (const auto& [name, e] : nodes_) out.push_back(name);
  return out;
}

}  // namespace chatsim::bus
