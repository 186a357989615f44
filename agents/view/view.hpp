#pragma once
// The view agent: camera offsets and ego motion from an instruction, and the new extrinsics
// they give for every frame and camera.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::agents::view {

// What an instruction changes (the "LLM" part); offsets are relative to the current view.
struct ViewChange {
  std::optional<std::array<double, 3>> translation_m;   // ego frame: x ahead, y left, z up
  std::optional<double> yaw_deg;                        // + turns left
  std::optional<double> pitch_deg;                      // + looks up
  std::optional<std::string> ego_motion;                // none, slow, fast
  // "closer to the kerb" (+) or "toward the middle of the road" (-): sideways by the road's
  // handedness, which only the scene knows (resolve_on_map).
  std::optional<double> toward_kerb_m;
  // "move the camera over to the oncoming lane": left, right, oncoming or parking, a lane of the
  // scene's map whose centre the view moves sideways to (resolve_on_map).
  std::optional<std::string> to_lane;
  // "move the camera forward to the junction": ahead to the middle of the first junction on the
  // ego's lane (resolve_on_map).
  bool to_junction = false;
  bool reset = false;
  bool needs_map() const { return toward_kerb_m || to_lane || to_junction; }
};
ViewChange parse_view(const std::string& instruction);
// Whether traffic keeps left: the nearest lane running against the ego's lies on its right.
bool keeps_left(const scene::Scene& scene);
// toward_kerb_m and to_lane turned into a sideways translation for the scene's handedness and
// lanes, from the view's current sideways offset current_y_m, and to_junction into the distance
// ahead to the junction. A lane or junction the map does not have stays in to_lane or
// to_junction, unresolved: the caller says so.
ViewChange resolve_on_map(ViewChange change, const scene::Scene& scene, double current_y_m = 0);
nlohmann::json to_json(const ViewChange& v);
ViewChange view_change_from_json(const nlohmann::json& j);

// The view part of the edit state.
struct ViewState {
  std::array<double, 3> translation_m{0, 0, 0};
  double yaw_deg = 0;
  double pitch_deg = 0;
  std::string ego_motion = "none";
};
ViewState apply(const ViewState& state, const ViewChange& change);
nlohmann::json to_json(const ViewState& v);
ViewState view_state_from_json(const nlohmann::json& j);

// Speeds the ego drives at for "slowly" and "fast" (m/s).
double ego_speed_mps(const std::string& ego_motion);

// New camera-to-world poses, frames x cameras: the view offset applied in each frame's ego
// frame (yaw and pitch turn the whole rig about the ego origin), and for ego motion the rig driving along
// the recorded path from frame 0 at the chosen speed.
std::vector<std::vector<Eigen::Isometry3d>> camera_poses(const scene::Scene& scene, const ViewState& view);

}  // namespace chatsim::agents::view
