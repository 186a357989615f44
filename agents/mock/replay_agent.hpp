#pragma once
// An agent that answers from a recording: each request is matched by its content (action,
// scene, arguments) to a recorded request of the same agent, and gets that request's
// recorded answer. A request never recorded gets a clear error, never a guess.
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "agents/core/agent.hpp"

namespace chatsim::agents {

struct RecordedExchange {
  AgentCall request;
  AgentOutcome response;
};

class ReplayAgent final : public Agent {
 public:
  ReplayAgent(std::string kind, const std::vector<RecordedExchange>& exchanges);
  const std::string& kind() const override { return kind_; }
  AgentOutcome handle(const AgentCall& call) override;
  size_t size() const { return answers_.size(); }

 private:
  using Key = std::tuple<std::string, std::string, std::string>;  // action, scene, canonical args
  static Key key_of(const AgentCall& call);
  std::string kind_;
  // Several identical requests in a recording are answered in their recorded order.
  std::map<Key, std::vector<AgentOutcome>> answers_;
  std::map<Key, size_t> used_;
};

}  // namespace chatsim::agents
