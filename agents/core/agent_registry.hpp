#pragma once
// The agent kinds of the design card and how to make each one.
#include <memory>
#include <string>
#include <vector>

#include "agents/core/agent.hpp"

namespace chatsim::agents {

struct AgentKindInfo {
  std::string kind;         // "motion"
  std::string process;      // "chatsim-motion"
  std::string role;         // one line for --help
  std::string pending;      // which issue brings its capability, while it is missing
};

const std::vector<AgentKindInfo>& agent_kinds();
const AgentKindInfo* find_agent_kind(const std::string& kind);

// The agent of that kind. Until a kind's capability lands, its agent answers every call with
// an explicit NotImplemented error, never a made-up result.
std::unique_ptr<Agent> make_agent(const std::string& kind);

}  // namespace chatsim::agents
