#pragma once
// Marking a convex region in a mask: the hull of points, in pixels or projected from the world.
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::render {

// Sets to 255 the pixels of `mask` (CV_8UC1) inside the convex hull of `points` (pixels).
void fill_convex_hull(cv::Mat& mask, const std::vector<cv::Point2f>& points);

// Sets to 255 the pixels of `mask` (CV_8UC1, the camera's size) inside the image of the convex
// hull of `world` points, clipped at the camera's near plane (a box beside the car reaches
// behind the camera: only what is in front shows).
void fill_projected_hull(cv::Mat& mask, const scene::Camera& camera, const Eigen::Isometry3d& camera_to_world,
                         const std::vector<Eigen::Vector3d>& world);

}  // namespace chatsim::render
