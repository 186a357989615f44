#include "common/util/log.hpp"

#include <cstdlib>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace chatsim {

void init_logging(const std::string& program, const std::string& default_level) {
  auto logger = spdlog::stderr_color_mt(program);
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("[%H:%M:%S.%e] [%^%l%$] [%n] %v");
  const char* env = std::getenv("CHATSIM_LOG_LEVEL");
  spdlog::set_level(spdlog::level::from_str(env != nullptr && *env != '\0' ? env : default_level));
}

}  // namespace chatsim
