#pragma once
// Labelled objects: 3D boxes tracked over frames (objects.json).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace chatsim::scene {

struct TrackPoint {
  int frame = 0;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // geometric centre, world frame
  double yaw = 0;                                    // about +z, world frame
};

struct ObjectTrack {
  std::string id;
  std::string category;                              // nuScenes style, e.g. vehicle.car
  std::optional<std::array<int, 3>> color_rgb;
  Eigen::Vector3d size_lwh = Eigen::Vector3d::Zero();
  std::vector<TrackPoint> track;                     // sorted by frame

  // The box at a frame: interpolated between labelled frames, none outside the track.
  std::optional<TrackPoint> at(int frame) const;
  bool has_category_prefix(const std::string& prefix) const;
};

// The 8 corners of a box (centre, size, yaw), in the box's frame of reference.
std::array<Eigen::Vector3d, 8> box_corners(const Eigen::Vector3d& center, const Eigen::Vector3d& size_lwh,
                                           double yaw);

}  // namespace chatsim::scene
