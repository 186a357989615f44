#pragma once
// Finding and ending a process's descendants (Linux /proc), so a launcher leaves nothing behind.
#include <sys/types.h>

#include <vector>

namespace chatsim::launch {

// Direct children of `parent`, read from /proc/*/stat.
std::vector<pid_t> children_of(pid_t parent);
// Children, grandchildren, ... of `root` (not root itself).
std::vector<pid_t> descendants_of(pid_t root);
// True while `pid` exists and is not a zombie.
bool process_alive(pid_t pid);

}  // namespace chatsim::launch
