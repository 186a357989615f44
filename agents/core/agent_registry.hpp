#pragma once
// The agent kinds of the design card and how to make each one.
#include <memory>
#include <string>
#include <vector>

#include "agents/core/agent.hpp"
#include "agents/manager/manager.hpp"

namespace chatsim::agents {

struct AgentKindInfo {
  std::string kind;         // "motion"
  std::string process;      // "chatsim-motion"
  std::string role;         // one line for --help
  std::string pending;      // which issue brings its capability, while it is missing
};

const std::vector<AgentKindInfo>& agent_kinds();
const AgentKindInfo* find_agent_kind(const std::string& kind);

// The agent of that kind, deciding with the LLM backend of $CHATSIM_LLM (default offline).
// The manager reaches the other agents through `caller` (over the bus in a process); without
// one it runs them in-process. Until a kind's capability lands, its agent answers every call
// with an explicit NotImplemented error, never a made-up result.
std::unique_ptr<Agent> make_agent(const std::string& kind, manager::AgentCaller caller = {});

// Runs the view, deletion, asset and motion agents in this process.
manager::AgentCaller local_caller(std::shared_ptr<llm::Backend> backend);

}  // namespace chatsim::agents
