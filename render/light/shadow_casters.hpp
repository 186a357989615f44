#pragma once
// The solids a labelled vehicle casts its shadow with, for the lighting estimate's shadow cue.
#include <vector>

#include <Eigen/Core>

namespace chatsim::render::light {

// A labelled object standing on the ground (shadow cue).
struct GroundBox {
  Eigen::Vector3d center;
  Eigen::Vector3d size_lwh;
  double yaw = 0;
  int frame = -1;                     // the instant it stands there; -1: in every view
  bool car_shaped = false;            // a car (belt line, greenhouse) rather than a box (truck, bus)
};

// Convex solids (their corners, world frame) whose union casts the object's shadow: the box
// itself, or for a car its lower body (the whole footprint up to the belt line) and its
// greenhouse, narrower and shorter, on top. A brick's shadow reaches past a car's at both ends
// and sides; on the demo street, fitting bricks' shadows put the sun 12-34 deg off.
// Proportions of a typical saloon: belt at 0.62 of the height; glass from 0.18 to 0.72 of the
// length from the rear at the belt, roof from 0.28 to 0.58; 0.86 of the width.
std::vector<std::vector<Eigen::Vector3d>> shadow_casters(const GroundBox& box);

}  // namespace chatsim::render::light
