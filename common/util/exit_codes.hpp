#pragma once
// Exit codes shared by every chatsim program, so scripts can tell failures apart.
namespace chatsim::exit_code {
inline constexpr int kOk = 0;
inline constexpr int kFailure = 1;         // the work failed (see the message)
inline constexpr int kUsage = 2;           // bad arguments or bad input file
inline constexpr int kBusUnavailable = 3;  // no bus proxy answered
}  // namespace chatsim::exit_code
