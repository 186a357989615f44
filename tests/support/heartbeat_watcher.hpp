#pragma once
// Records who is beating on a bus: node name -> pid of its latest heartbeat.
#include <map>
#include <string>

#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"

namespace chatsim::test_support {

class HeartbeatWatcher {
 public:
  // Subscribes node to heartbeats; call before node.start() or after (it re-syncs).
  explicit HeartbeatWatcher(bus::Node& node) : node_(node) {
    node_.subscribe(std::string(bus::topics::kHeartbeat), [this](const bus::Message& m) {
      const auto* hb = m.payload<msgs::Heartbeat>();
      if (hb->state() != msgs::NodeState::Stopping) pids[std::string(bus::view(hb->node()))] = hb->pid();
    });
  }

  // Spins the node until pred() holds or timeout passes; returns pred().
  template <class Pred>
  bool until(Pred pred, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!pred() && std::chrono::steady_clock::now() < end) node_.spin_once(std::chrono::milliseconds(10));
    return pred();
  }

  bool wait_for(const std::string& name, std::chrono::milliseconds timeout) {
    return until([&] { return pids.count(name) != 0; }, timeout);
  }

  // For a process that replaces another of the same name: beats of the one it replaced may
  // still be queued here, so only a beat from this pid counts.
  bool wait_for(const std::string& name, int pid, std::chrono::milliseconds timeout) {
    return until([&] { return pids.count(name) != 0 && pids[name] == pid; }, timeout);
  }

  std::map<std::string, int> pids;

 private:
  bus::Node& node_;
};

}  // namespace chatsim::test_support
