#pragma once
// When (and whether) to restart a process that exited. Pure logic, unit-tested.
#include <optional>
#include <string>

namespace chatsim::launch {

enum class RespawnPolicy { Never, OnFailure, Always };

// "never", "on-failure", "always"; nullopt for anything else.
std::optional<RespawnPolicy> parse_respawn_policy(const std::string& text);
const char* to_string(RespawnPolicy policy);

struct BackoffConfig {
  double initial_delay_s = 0.5;
  double max_delay_s = 10.0;
  int max_respawns = 20;          // consecutive quick failures allowed; 0 = unlimited
  double stable_after_s = 10.0;   // a run this long resets the back-off
};

class RespawnBackoff {
 public:
  RespawnBackoff(RespawnPolicy policy, BackoffConfig config) : policy_(policy), config_(config) {}

  // Called when the process exited after running `ran_s` seconds. Returns the delay before
  // restarting it, or nullopt if it must stay down.
  std::optional<double> on_exit(bool failed, double ran_s);

  int consecutive() const { return consecutive_; }
  bool exhausted() const { return exhausted_; }

 private:
  RespawnPolicy policy_;
  BackoffConfig config_;
  int consecutive_ = 0;
  bool exhausted_ = false;
};

}  // namespace chatsim::launch
