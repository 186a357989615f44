#pragma once
// The view, deletion, asset and motion agents: their "LLM" part (an llm::Backend) turns the
// instruction into a configuration, their role functions execute it on the scene.
#include <memory>

#include "agents/core/agent.hpp"
#include "agents/llm/llm_backend.hpp"

namespace chatsim::agents {

std::unique_ptr<Agent> make_view_agent(std::shared_ptr<llm::Backend> backend);
std::unique_ptr<Agent> make_deletion_agent(std::shared_ptr<llm::Backend> backend);
std::unique_ptr<Agent> make_asset_agent(std::shared_ptr<llm::Backend> backend);
std::unique_ptr<Agent> make_motion_agent(std::shared_ptr<llm::Backend> backend);

}  // namespace chatsim::agents
