#include "render/projected_hull.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"

namespace chatsim::render {

void fill_projected_hull(cv::Mat& mask, const scene::Camera& camera, const Eigen::Isometry3d& camera_to_world,
                         const std::vector<Eigen::Vector3d>& world) {
  const auto projected = scene::project_clipped(camera, camera_to_world, world);
  if (projected.empty()) return;
  std::vector<cv::Point2f> px;
  for (const auto& p : projected) px.emplace_back(float(p.x()), float(p.y()));
  std::vector<cv::Point2f> hull_f;
  cv::convexHull(px, hull_f);
  std::vector<cv::Point> hull;
  for (const auto& p : hull_f) hull.emplace_back(int(std::lround(p.x)), int(std::lround(p.y)));
  cv::fillConvexPoly(mask, hull, 255);
}

}  // namespace chatsim::render
