#pragma once
// The deletion agent's rendering role: remove the chosen objects from a stage's images (the
// ground map gathered from the captured images, the radiance field without those objects for
// what stood behind them) and write the next stage.
#include "agents/core/agent.hpp"

namespace chatsim::agents::render {

// action "inpaint" (args: a RenderJob with removed, in and out).
AgentOutcome deletion_inpaint(const AgentCall& call);

}  // namespace chatsim::agents::render
