#pragma once
// Where the labelled objects that move are in an image, padded to take in their shadows: the
// novel-view eval scores the static background apart from them (what the moving cars cost and
// what the background costs are different problems).
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::render::gs {

struct MovingMaskOptions {
  double min_move_m = 0.2;  // an object whose box moves less than this over its track is parked
  double pad_m = 0.3;       // around the box
  double ground_pad_m = 1.0;  // around the footprint on the ground: the car's shadow and contact darkening
};

// Per object of the scene: does its box move along its track.
std::vector<bool> moving_objects(const scene::Scene& scene, double min_move_m = MovingMaskOptions{}.min_move_m);

// CV_8UC1, 255 where a moving object's padded box (or its padded footprint on the ground) at
// `time_s` covers the image of `camera` at `camera_to_world`.
cv::Mat moving_object_mask(const scene::Scene& scene, const std::vector<bool>& moving, const scene::Camera& camera,
                           const Eigen::Isometry3d& camera_to_world, double time_s, const MovingMaskOptions& options = {});

}  // namespace chatsim::render::gs
