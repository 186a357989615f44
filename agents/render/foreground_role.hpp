#pragma once
// The foreground agent's role: path-trace the added vehicles into a stage's images. Light comes
// from the scene's estimated sky dome and sun (estimated once per scene, cached) blended with
// the surroundings the radiance field sees from where the vehicle is (env = surround + T x sky;
// the sun dimmed by what blocks it there). Vehicles are rendered only over the image area they
// and their shadows cover, with a shadow catcher on the ground; the composite keeps scene
// objects that are nearer than the vehicle in front of it.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "agents/core/agent.hpp"
#include "render/light/light_estimate.hpp"

namespace chatsim::agents::render {

struct ForegroundSettings {
  int spp = 32;
  int max_depth = 3;
};

// action "render" (args: a RenderJob with added, in and out; optional spp).
AgentOutcome foreground_render(const AgentCall& call);

// action "light": the scene's lighting estimate, made once before the rendering stages so that
// the workers of the foreground and deletion stages read it rather than each making their own.
// Answers the estimate's JSON and "estimated" (false: it was cached).
AgentOutcome foreground_light(const AgentCall& call);

// The scene's lighting estimate, cached beside its model (light.json, sky.exr); `estimated`
// tells whether this call made it.
chatsim::render::light::LightEstimate scene_light(const scene::Scene& scene, bool* estimated = nullptr);

// An added vehicle's pose (world: bottom centre on the ground, yaw) at a scene time, from its
// trajectory; none when the trajectory has ended (it left the scene).
std::optional<Eigen::Isometry3d> added_vehicle_pose(const scene::Scene& scene, const nlohmann::json& vehicle, double time_s);

}  // namespace chatsim::agents::render
