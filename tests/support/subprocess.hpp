#pragma once
// Starting and ending real processes from tests.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/scratch_dir.hpp"

namespace chatsim::test_support {

inline std::string bin(const std::string& name) { return std::string(CHATSIM_BIN_DIR) + "/" + name; }

// A per-test-process path in the scratch folder.
inline std::filesystem::path temp_path(const std::string& name) {
  return chatsim::scratch::dir() /
         ("chatsim-test-" + std::to_string(getpid()) + "-" + name);
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// fork/exec with stdout/stderr to `log` (or inherited when empty).
inline pid_t spawn(const std::vector<std::string>& args, const std::string& log = "") {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    // Only async-signal-safe calls here: the test process has other threads (ZeroMQ's).
    if (!log.empty()) {
      const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd >= 0) {
        dup2(fd, 1);
        dup2(fd, 2);
      }
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

// Exit status (as from waitpid) if pid ended within timeout.
inline std::optional<int> wait_for(pid_t pid, std::chrono::milliseconds timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return status;
    if (std::chrono::steady_clock::now() > end) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

// Ends pid for sure (tests always clean up).
inline void kill_and_reap(pid_t pid) {
  if (pid <= 0) return;
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
}

// How many processes of this name are children of the test (left behind ones show here).
inline int count_children(const std::string& name) {
  const std::string cmd = "pgrep -x " + name + " -P " + std::to_string(getpid()) + " | wc -l";
  FILE* p = popen(cmd.c_str(), "r");
  int n = 0;
  if (p != nullptr) {
    if (fscanf(p, "%d", &n) != 1) n = 0;
    pclose(p);
  }
  return n;
}

// How many live processes of this name carry `marker` in their environment: finds processes
// left behind even after their parent died and they were re-parented.
inline int count_with_env(const std::string& name, const std::string& marker) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream comm(e.path() / "comm");
    std::string c;
    if (!std::getline(comm, c) || c != name) continue;
    std::ifstream env(e.path() / "environ", std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(env)), std::istreambuf_iterator<char>());
    if (all.find(marker) != std::string::npos) ++n;
  }
  return n;
}

struct ScopedProcess {
  pid_t pid = -1;
  explicit ScopedProcess(pid_t p) : pid(p) {}
  ~ScopedProcess() { kill_and_reap(pid); }
  std::optional<int> wait(std::chrono::milliseconds t) {
    auto s = wait_for(pid, t);
    if (s) pid = -1;
    return s;
  }
};

}  // namespace chatsim::test_support
