#pragma once
// The procedural demo street as a layout (issue #4, part 3, without the rendered images yet):
// a straight road with two lanes each way, parking lanes on both sides, a cross street, parked
// and moving vehicles of several types and colours, a pedestrian, and a three-camera front rig
// (Waymo-like, ~50 degree FOV, overlapping) on an ego car driving at 8 m/s. Seeded: the same
// seed gives the same scene.
#include <cstdint>

#include "common/scene/scene.hpp"

namespace chatsim::scene {

struct DemoOptions {
  uint64_t seed = 1;
  int frames = 40;
  double frame_rate_hz = 10;
  int width = 640;
  int height = 426;
  double ego_speed_mps = 8;
};

Scene demo_layout(const DemoOptions& options);

}  // namespace chatsim::scene
