#pragma once
// Rendering an edit state, in the paper's order: the radiance field (trained once per scene),
// the background of the requested view, deletion, then the added vehicles; each stage asked of
// its agent through the caller (over the bus in the processes), each stage's output cached
// under a key of what it depends on, so a later round renders only what changed. The result
// folder gets per-camera PNG frames, depth, the side-by-side video, labels (JSON and KITTI) and
// edit.json, written under a temporary name and swapped in when complete. It must be new, empty
// or a result chatsim wrote (common/util/output_dir.hpp): anything else is refused before any work.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "agents/core/agent.hpp"
#include "agents/manager/manager.hpp"

namespace chatsim::agents::render {

struct RenderTask {
  std::string scene_dir;
  nlohmann::json edit_state;
  std::string output_dir;
  std::string preset = "fast";      // radiance field preset
  int chunk = 12;                   // images per request to the background and foreground agents
  int foreground_spp = 32;
  bool force_output = false;        // output_dir may hold a chatsim output of another kind (--force)
};

// The rendering presets a user picks (chatsim run --preset): the radiance field's preset and
// the added vehicles' samples per pixel. Throws std::invalid_argument for an unknown name.
struct RenderPreset {
  std::string model;
  int foreground_spp;
};
RenderPreset render_preset(const std::string& name);  // draft, fast (also when empty), quality

// stage (background, deletion, foreground, composition, encoding, training), 0..1, message.
using PipelineProgress = std::function<void(const std::string&, double, const std::string&)>;

// With `fanout`, the background and foreground chunks are spread over that kind's processes.
AgentOutcome render_edit(const manager::AgentCaller& call, const RenderTask& task, const PipelineProgress& progress = {},
                         const manager::FanoutCaller& fanout = {});

}  // namespace chatsim::agents::render
