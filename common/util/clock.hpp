#pragma once
#include <chrono>
#include <cstdint>

namespace chatsim {

// Wall-clock time in nanoseconds since the Unix epoch (message stamps, deadlines).
inline int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Monotonic seconds, for measuring durations.
inline double mono_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace chatsim
