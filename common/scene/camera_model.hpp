#pragma once
// Pinhole projection between world points and pixels (OpenCV camera frame: x right, y down,
// z forward), and LiDAR point files (float32 x, y, z, intensity in the ego frame).
#include <filesystem>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "common/scene/scene.hpp"

namespace chatsim::scene {

struct Projection {
  Eigen::Vector2d pixel;   // (u, v), may lie outside the image
  double depth = 0;        // along the optical axis, metres
  bool in_image = false;
};

// None when the point is behind the camera (depth below near_m).
std::optional<Projection> project(const Camera& camera, const Eigen::Isometry3d& camera_to_world,
                                  const Eigen::Vector3d& world, double near_m = 0.05);
// The pixels of world points as far as their convex hull lies in front of the camera: points
// behind the near plane are replaced by where the segments to the points in front cross it, so
// a box reaching past the camera covers what is in front of it, not the whole image. Empty
// when every point is behind. Clamped to +-1e5: points near the plane can project very far.
std::vector<Eigen::Vector2d> project_clipped(const Camera& camera, const Eigen::Isometry3d& camera_to_world,
                                             const std::vector<Eigen::Vector3d>& world, double near_m = 0.1);
// The world point at that pixel and depth (along the optical axis).
Eigen::Vector3d unproject(const Camera& camera, const Eigen::Isometry3d& camera_to_world,
                          const Eigen::Vector2d& pixel, double depth);

struct LidarPoint {
  Eigen::Vector3f xyz;
  float intensity = 0;
};

// Reads a LiDAR file of `stride` float32 values per point (4 for ours, 5 for nuScenes .pcd.bin).
std::vector<LidarPoint> read_lidar(const std::filesystem::path& file, int stride = 4);

}  // namespace chatsim::scene
