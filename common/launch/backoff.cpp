#include "common/launch/backoff.hpp"

#include <algorithm>
#include <cmath>

namespace chatsim::launch {

std::optional<RespawnPolicy> parse_respawn_policy(const std::string& text) {
  if (text == "never") return RespawnPolicy::Never;
  if (text == "on-failure") return RespawnPolicy::OnFailure;
  if (text == "always") return RespawnPolicy::Always;
  return std::nullopt;
}

const char* to_string(RespawnPolicy policy) {
  switch (policy) {
    case RespawnPolicy::Never: return "never";
    case RespawnPolicy::OnFailure: return "on-failure";
    case RespawnPolicy::Always: return "always";
  }
  return "?";
}

std::optional<double> RespawnBackoff::on_exit(bool failed, double ran_s) {
  if (policy_ == RespawnPolicy::Never) return std::nullopt;
  if (policy_ == RespawnPolicy::OnFailure && !failed) return std::nullopt;
  if (ran_s >= config_.stable_after_s) consecutive_ = 0;
  if (config_.max_respawns > 0 && consecutive_ >= config_.max_respawns) {
    exhausted_ = true;
    return std::nullopt;
  }
  const double delay =
      std::min(config_.max_delay_s, config_.initial_delay_s * std::pow(2.0, consecutive_));
  ++consecutive_;
  return delay;
}

}  // namespace chatsim::launch
