#pragma once
// User-facing commands need agent processes: use the bus that is running, or start the
// processes they need on an OS-chosen port and stop them when done.
#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace chatsim::launch {
class Launcher;
}

namespace chatsim::cli {

class ProcessGraph {
 public:
  // bus: an endpoint to use as is; empty: $CHATSIM_BUS if a proxy answers there, else start
  // chatsim-bus and the given agents (chatsim-<kind>) privately.
  ProcessGraph(const std::string& bus, const std::vector<std::string>& agents);
  ~ProcessGraph();  // stops what it started

  const std::string& endpoint() const { return endpoint_; }
  bool started_own() const { return launcher_ != nullptr; }

 private:
  std::string endpoint_;
  std::unique_ptr<launch::Launcher> launcher_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
  std::atomic<int> exit_code_{-1};
  std::filesystem::path endpoint_file_;
};

}  // namespace chatsim::cli
