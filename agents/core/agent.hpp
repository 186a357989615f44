#pragma once
// What every agent is, without any transport: a call with plain inputs in, an outcome out.
// Processes (processes/*_main.cpp) wire an Agent to the bus; tests call it directly.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

namespace chatsim::agents {

enum class ErrorKind { NotImplemented, BadRequest, Unavailable, Internal };

struct AgentCall {
  std::string action;        // e.g. "decide", "plan", "render"
  std::string scene;         // scene directory
  nlohmann::json args;       // the agent's JSON configuration
  double timeout_s = 0;      // how long the caller waits (0: the caller's default); long work sets it
};

struct AgentOutcome {
  bool ok = false;
  nlohmann::json result;     // on success
  ErrorKind error = ErrorKind::Internal;
  std::string message;       // on failure: what went wrong and what to do

  static AgentOutcome success(nlohmann::json result) { return {true, std::move(result), {}, {}}; }
  static AgentOutcome failure(ErrorKind kind, std::string message) {
    return {false, nullptr, kind, std::move(message)};
  }
};

class Agent {
 public:
  virtual ~Agent() = default;
  virtual const std::string& kind() const = 0;
  virtual AgentOutcome handle(const AgentCall& call) = 0;
};

}  // namespace chatsim::agents
