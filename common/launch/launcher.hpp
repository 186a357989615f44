#pragma once
// Starts a launch file's process graph in order, waits for each to be ready (heartbeat),
// keeps it up by its respawn policy, and stops all of it, grandchildren included.
#include <sys/types.h>

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/bus/heartbeat_monitor.hpp"
#include "common/launch/backoff.hpp"
#include "common/launch/launch_file.hpp"

namespace chatsim::bus {
class Node;
}

namespace chatsim::launch {

struct LauncherOptions {
  std::string bus_override;               // replaces the file's bus endpoint
  std::filesystem::path endpoint_file;    // where to write the bus endpoint once known
  std::filesystem::path executable_dir;   // where chatsim-* binaries are
};

class Launcher {
 public:
  Launcher(LaunchFile file, LauncherOptions options);
  ~Launcher();

  // Runs until `stop` is set or every process is down for good. Returns an exit code:
  // 0 stopped cleanly, 1 a process failed to start or stayed down after failing.
  int run(const std::atomic<bool>& stop);

  const std::string& bus_endpoint() const { return bus_; }

 private:
  struct Child {
    const ProcessSpec* spec = nullptr;
    pid_t pid = -1;
    double started_s = 0;
    double restart_at_s = -1;   // scheduled respawn, monotonic seconds
    bool done = false;          // will not run again
    bool failed = false;
    RespawnBackoff backoff{RespawnPolicy::Never, {}};
  };

  bool start_in_order(const std::atomic<bool>& stop);
  bool wait_ready(Child& child, const std::atomic<bool>& stop);
  bool wait_for_endpoint_file(Child& child, const std::filesystem::path& file,
                              const std::atomic<bool>& stop);
  void ensure_bus_node(double timeout_s);
  pid_t spawn(Child& child);
  std::vector<std::string> command_line(const ProcessSpec& spec) const;
  std::string resolve(const std::string& executable) const;
  void reap(bool stopping);
  // Starts again every child whose scheduled respawn is due.
  void respawn_due();
  void poll_bus(double seconds);
  void stop_all();

  LaunchFile file_;
  LauncherOptions options_;
  std::string bus_;
  std::filesystem::path bus_port_file_;
  std::vector<Child> children_;
  std::unique_ptr<bus::Node> node_;
  bus::HeartbeatMonitor monitor_;
  struct Beat {
    double seen_s = 0;
    int pid = 0;
  };
  std::map<std::string, Beat> last_beat_;
  double orphans_reaped_s_ = 0;
};

}  // namespace chatsim::launch
