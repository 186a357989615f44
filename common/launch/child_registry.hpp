#pragma once
// The children of every Launcher in this process. Several launchers can run in one process
// (two chat sessions, each starting its own agents): each must reap and end only its own, or
// one would take the other's exit statuses and kill its processes when it stops.
#include <sys/types.h>

#include <vector>

namespace chatsim::launch::child_registry {

void add(pid_t pid);
void remove(pid_t pid);
bool owned(pid_t pid);
// Processes below this one that no launcher owns (orphans adopted by this subreaper, escaped
// process groups): every descendant except the launchers' children and what lies below them.
std::vector<pid_t> unowned_descendants();
// Reaps this process's exited children that no launcher owns (adopted orphans).
void reap_unowned();

}  // namespace chatsim::launch::child_registry
