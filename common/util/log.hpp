#pragma once
#include <string>

namespace chatsim {

// Logs to stderr as "[time] [level] [program] message". The level comes from
// $CHATSIM_LOG_LEVEL (trace, debug, info, warn, error, off), else `default_level`.
void init_logging(const std::string& program, const std::string& default_level = "info");

}  // namespace chatsim
