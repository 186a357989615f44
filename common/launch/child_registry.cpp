#include "common/launch/child_registry.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <mutex>
#include <set>

#include "common/launch/process_tree.hpp"

namespace chatsim::launch::child_registry {
namespace {

std::mutex mu;
std::set<pid_t> pids;

std::set<pid_t> snapshot() {
  std::lock_guard lock(mu);
  return pids;
}

}  // namespace

void add(pid_t pid) {
  std::lock_guard lock(mu);
  pids.insert(pid);
}

void remove(pid_t pid) {
  std::lock_guard lock(mu);
  pids.erase(pid);
}

bool owned(pid_t pid) {
  std::lock_guard lock(mu);
  return pids.count(pid) != 0;
}

std::vector<pid_t> unowned_descendants() {
  std::set<pid_t> keep = snapshot();
  for (pid_t p : std::vector<pid_t>(keep.begin(), keep.end()))
    for (pid_t d : descendants_of(p)) keep.insert(d);
  std::vector<pid_t> out = descendants_of(getpid());
  out.erase(std::remove_if(out.begin(), out.end(), [&](pid_t p) { return keep.count(p) != 0; }), out.end());
  return out;
}

void reap_unowned() {
  for (pid_t p : children_of(getpid()))
    if (!owned(p) && !process_alive(p)) waitpid(p, nullptr, WNOHANG);
}

}  // namespace chatsim::launch::child_registry
