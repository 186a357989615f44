#pragma once
// chatsim-mock's script: canned responses for one agent kind, with optional delay and
// failure injection, in YAML or JSON. Example (see launch/mocks/motion.yaml):
//   agent: motion
//   seed: 7
//   failure_rate: 0.1          # share of calls answered with an injected Internal error
//   delay_ms: 20               # default delay before every answer
//   responses:
//     - match: {action: plan, args_contains: porsche}
//       delay_ms: 100
//       result: {trajectory: []}
//     - match: {action: render}
//       error: {code: not_implemented, message: "no renderer in this mock"}
//     - result: {}             # no match: answers everything else
#include <filesystem>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agents/core/agent.hpp"

namespace chatsim::agents {

class MockScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MockResponse {
  std::optional<std::string> match_action;
  std::optional<std::string> match_args_contains;
  int delay_ms = -1;                    // -1: the script's default
  bool is_error = false;
  nlohmann::json result;
  ErrorKind error = ErrorKind::Internal;
  std::string error_message;
};

struct MockScript {
  std::string agent;
  uint64_t seed = 1;
  double failure_rate = 0.0;
  int delay_ms = 0;
  std::vector<MockResponse> responses;
};

MockScript load_mock_script(const std::filesystem::path& path);
MockScript parse_mock_script(const std::string& text, const std::filesystem::path& path_for_messages);

// An Agent answering from a script. Deterministic for a given seed and call sequence.
class MockAgent final : public Agent {
 public:
  explicit MockAgent(MockScript script);
  const std::string& kind() const override { return script_.agent; }
  AgentOutcome handle(const AgentCall& call) override;

  // The delay the last handle() asked for (handle() sleeps it itself).
  int last_delay_ms() const { return last_delay_ms_; }

 private:
  MockScript script_;
  std::mt19937_64 rng_;
  int last_delay_ms_ = 0;
};

}  // namespace chatsim::agents
