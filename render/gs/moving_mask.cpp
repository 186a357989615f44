#include "render/gs/moving_mask.hpp"

#include <cmath>

#include "common/scene/objects.hpp"
#include "render/gs/model.hpp"
#include "render/projected_hull.hpp"

namespace chatsim::render::gs {

std::vector<bool> moving_objects(const scene::Scene& s, double min_move_m) {
  std::vector<bool> out(s.objects.size(), false);
  for (size_t k = 0; k < s.objects.size(); ++k) {
    const auto& t = s.objects[k].track;
    for (const auto& p : t) out[k] = out[k] || (p.center - t.front().center).norm() >= min_move_m;
  }
  return out;
}

cv::Mat moving_object_mask(const scene::Scene& s, const std::vector<bool>& moving, const scene::Camera& cam,
                           const Eigen::Isometry3d& pose, double time_s, const MovingMaskOptions& o) {
  cv::Mat mask(cam.height, cam.width, CV_8U, cv::Scalar(0));
  for (size_t k = 0; k < s.objects.size() && k < moving.size(); ++k) {
    if (!moving[k]) continue;
    const auto& obj = s.objects[k];
    const auto T = object_pose(s, obj, time_s);
    if (!T) continue;
    const Eigen::Vector3d c = T->translation();
    const double yaw = std::atan2(T->linear()(1, 0), T->linear()(0, 0));
    std::vector<Eigen::Vector3d> pts;
    for (const auto& p : scene::box_corners(c, obj.size_lwh + Eigen::Vector3d::Constant(2 * o.pad_m), yaw)) pts.push_back(p);
    const double ground = c.z() - obj.size_lwh.z() / 2;
    const Eigen::Vector3d footprint(obj.size_lwh.x() + 2 * o.ground_pad_m, obj.size_lwh.y() + 2 * o.ground_pad_m, 0);
    for (const auto& p : scene::box_corners(Eigen::Vector3d(c.x(), c.y(), ground), footprint, yaw)) pts.push_back(p);
    fill_projected_hull(mask, cam, pose, pts);
  }
  return mask;
}

}  // namespace chatsim::render::gs
