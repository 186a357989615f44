#pragma once
// Which nodes are alive, from their heartbeats. Transport-free: feed it observations and
// the current time; it says who is overdue, by name.
#include <map>
#include <string>
#include <vector>

namespace chatsim::bus {

class HeartbeatMonitor {
 public:
  // A node is overdue after `missed_beats` of its own periods without a heartbeat
  // (and never sooner than min_timeout_s).
  explicit HeartbeatMonitor(double missed_beats = 4.0, double min_timeout_s = 1.0)
      : missed_beats_(missed_beats), min_timeout_s_(min_timeout_s) {}

  void observe(const std::string& node, double now_s, double period_s, bool stopping = false);

  bool seen(const std::string& node) const { return nodes_.count(node) != 0; }
  bool alive(const std::string& node, double now_s) const;
  // Whether its last heartbeat said it was stopping, and when that beat came (-1: never seen).
  bool stopped(const std::string& node) const;
  double last_seen_s(const std::string& node) const;
  // Nodes that beat once and then fell silent without saying they were stopping.
  std::vector<std::string> overdue(double now_s) const;
  std::vector<std::string> names() const;

 private:
  struct Entry {
    double last_s = 0;
    double period_s = 0.5;
    bool stopped = false;
  };
  double timeout(const Entry& e) const;

  double missed_beats_;
  double min_timeout_s_;
  std::map<std::string, Entry> nodes_;
};

}  // namespace chatsim::bus
