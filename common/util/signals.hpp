#pragma once
#include <atomic>

namespace chatsim {

// Installs SIGINT/SIGTERM handlers that set the returned flag; main loops poll it.
// SIGPIPE is ignored (a closed pipe is an error value, not a death).
const std::atomic<bool>& install_stop_signals();

// The signal that set the flag (0 if none).
int stop_signal();

}  // namespace chatsim
