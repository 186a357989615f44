#include "render/light/shadow_casters.hpp"

#include <utility>

#include <Eigen/Geometry>

#include "common/scene/objects.hpp"

namespace chatsim::render::light {

std::vector<std::vector<Eigen::Vector3d>> shadow_casters(const GroundBox& b) {
  const auto corners = scene::box_corners(b.center, b.size_lwh, b.yaw);
  if (!b.car_shaped) return {std::vector<Eigen::Vector3d>(corners.begin(), corners.end())};
  const double l = b.size_lwh.x(), w = b.size_lwh.y(), h = b.size_lwh.z(), belt = 0.62 * h;
  const double ground = b.center.z() - h / 2;
  const auto lower = scene::box_corners(Eigen::Vector3d(b.center.x(), b.center.y(), ground + belt / 2), Eigen::Vector3d(l, w, belt), b.yaw);
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(b.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::vector<Eigen::Vector3d> glass;
  for (const auto& [from_rear, z] : {std::pair{0.18, belt}, {0.72, belt}, {0.28, h}, {0.58, h}})
    for (const double side : {-0.43, 0.43})
      glass.push_back(Eigen::Vector3d(b.center.x(), b.center.y(), ground + z) + yaw * Eigen::Vector3d((from_rear - 0.5) * l, side * w, 0));
  return {std::vector<Eigen::Vector3d>(lower.begin(), lower.end()), glass};
}

}  // namespace chatsim::render::light
