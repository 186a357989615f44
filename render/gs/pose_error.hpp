#pragma once
// How far the poses training used are from the truth, on a scene that records it (the demo
// scene's ground_truth/poses.json): the scene's poses, where training starts, and the refined
// ones (those x the learned per-camera and per-image corrections), per camera. This measures pose refinement
// itself, not through rendered pixels.
#include <optional>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"
#include "render/gs/model.hpp"

namespace chatsim::render::gs {

// {"cameras": {name: {count, initial: {rotation_deg, rotation_xyz_deg, translation_m}, refined: {...}}},
// "all": {...}} with medians over the images training refined; rotation_xyz_deg is the signed
// error about the camera's own x (right), y (down) and z (forward) axes (which way refinement is
// off). nullopt when the scene has no true poses or the model refined none.
std::optional<nlohmann::json> evaluate_pose_error(const RadianceField& model, const scene::Scene& scene);

}  // namespace chatsim::render::gs
