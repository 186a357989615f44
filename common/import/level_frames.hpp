#pragma once
// nuScenes ego poses are planar: their height is always 0, whatever the road does. Boxes are
// labelled against each key frame's LiDAR, so a parked car's height then drifts with the rig's
// true height (scene-0916: by up to 2.4 m over the clip), and so would every camera and LiDAR
// sweep against the others. Per frame, a height and a tilt (a plane through the ego) that bring
// the static labelled objects back to one height each are fitted, and applied to that frame's
// ego pose, images and boxes together (what the sensor saw relative to the rig is unchanged).
#include <map>

#include "common/scene/scene.hpp"

namespace chatsim::import {

struct FrameLevel {
  double height = 0;   // m, added at the ego
  double slope_x = 0;  // dz/dx of the correction (world frame), about the ego
  double slope_y = 0;  // dz/dy
  int objects = 0;     // static objects it was fitted to (0: interpolated from the neighbours)
};

struct LevelOptions {
  double max_static_travel_m = 1.5;  // an object whose box centre ranges less than this in x and y is static
  int min_track_frames = 5;          // ... and is labelled in at least this many frames
  int min_objects_per_frame = 6;     // fewer in a frame: its correction is interpolated
  double outlier_m = 0.5;            // a box this far from its object's height after the fit is left out
};

// The corrections, by frame index; frame 0's is zero (the world stays the first ego pose). Empty
// when fewer than two frames have enough static objects.
std::map<int, FrameLevel> fit_frame_levels(const scene::Scene& scene, const LevelOptions& options = {});

// Applies them to each frame's ego pose, its images' poses and the boxes labelled at it.
void apply_frame_levels(scene::Scene& scene, const std::map<int, FrameLevel>& levels);

}  // namespace chatsim::import
