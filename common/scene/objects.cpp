#include "common/scene/objects.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chatsim::scene {

std::optional<TrackPoint> ObjectTrack::at(int frame) const {
  if (track.empty() || frame < track.front().frame || frame > track.back().frame) return std::nullopt;
  const auto it = std::lower_bound(track.begin(), track.end(), frame,
                                   [](const TrackPoint& p, int f) { return p.frame < f; });
  if (it->frame == frame) return *it;
  const auto& b = *it;
  const auto& a = *(it - 1);
  const double w = double(frame - a.frame) / double(b.frame - a.frame);
  double dyaw = std::remainder(b.yaw - a.yaw, 2 * std::numbers::pi);
  return TrackPoint{frame, a.center + w * (b.center - a.center), a.yaw + w * dyaw};
}

bool ObjectTrack::has_category_prefix(const std::string& prefix) const {
  if (category.compare(0, prefix.size(), prefix) != 0) return false;
  return category.size() == prefix.size() || category[prefix.size()] == '.';
}

std::array<Eigen::Vector3d, 8> box_corners(const Eigen::Vector3d& c, const Eigen::Vector3d& s, double yaw) {
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  std::array<Eigen::Vector3d, 8> out;
  int i = 0;
  for (int dx : {-1, 1})
    for (int dy : {-1, 1})
      for (int dz : {-1, 1}) {
        const double x = dx * s.x() / 2, y = dy * s.y() / 2;
        out[i++] = c + Eigen::Vector3d(cy * x - sy * y, sy * x + cy * y, dz * s.z() / 2);
      }
  return out;
}

}  // namespace chatsim::scene
