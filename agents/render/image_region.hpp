#pragma once
// Where world points (an inserted vehicle's box and its shadow) fall in an image: the area the
// foreground agent path traces, so it renders only what can change.
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::agents::render {

// The padded bounding rectangle of the points' projections, clipped to the image. Points
// behind the camera are replaced by where the segments to the ones in front cross the near
// plane, so a vehicle passing beside the camera does not make the whole frame its area.
// Empty when every point is behind the camera or the area is outside the image.
cv::Rect image_region(const std::vector<Eigen::Vector3d>& world, const scene::Camera& cam,
                      const Eigen::Isometry3d& camera_to_world, int pad_px = 8);

// Overlapping rectangles merged into their bounding rectangle, until none overlap: rendering
// each vehicle's area alone skips the empty space between far-apart vehicles, and merging
// keeps any pixel from being composited twice.
std::vector<cv::Rect> merge_overlapping(std::vector<cv::Rect> rects);

}  // namespace chatsim::agents::render
