#pragma once
// The agents of the processes that render: the background agent (radiance field), the deletion
// agent (its decisions plus inpainting), the foreground agent (path tracing and compositing),
// and a manager whose rounds can be rendered through the pipeline.
#include <memory>
#include <string>

#include "agents/core/agent.hpp"
#include "agents/manager/manager.hpp"
#include "agents/render/render_pipeline.hpp"

namespace chatsim::agents::render {

// background, deletion or foreground (others: nullptr). `progress` reports long work.
std::unique_ptr<Agent> make_render_agent(const std::string& kind, const PipelineProgress& progress = {});

// The manager with the rendering pipeline, reaching every agent through `caller` (and spreading
// rendering over several worker processes through `fanout`, when given).
std::unique_ptr<Agent> make_rendering_manager(manager::AgentCaller caller, const PipelineProgress& progress = {},
                                              manager::FanoutCaller fanout = {});

}  // namespace chatsim::agents::render
