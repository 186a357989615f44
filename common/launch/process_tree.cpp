#include "common/launch/process_tree.hpp"

#include <signal.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace chatsim::launch {
namespace {

// Fields of /proc/PID/stat after the parenthesised command name (which may hold spaces).
bool read_stat(pid_t pid, char& state, pid_t& ppid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return false;
  const auto close = line.rfind(')');
  if (close == std::string::npos || close + 4 >= line.size()) return false;
  state = line[close + 2];
  ppid = static_cast<pid_t>(std::strtol(line.c_str() + close + 4, nullptr, 10));
  return true;
}

}  // namespace

std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(name));
    char state = 0;
    pid_t ppid = 0;
    if (read_stat(pid, state, ppid) && ppid == parent) out.push_back(pid);
  }
  return out;
}

std::vector<pid_t> descendants_of(pid_t root) {
  std::vector<pid_t> out;
  std::vector<pid_t> frontier{root};
  while (!frontier.empty()) {
    const pid_t p = frontier.back();
    frontier.pop_back();
    for (pid_t c : children_of(p)) {
      out.push_back(c);
      frontier.push_back(c);
    }
  }
  return out;
}

bool process_alive(pid_t pid) {
  char state = 0;
  pid_t ppid = 0;
  if (!read_stat(pid, state, ppid)) return false;
  return state != 'Z' && state != 'X';
}

}  // namespace chatsim::launch
