#include "render/projected_hull.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"

namespace chatsim::render {

void fill_convex_hull(cv::Mat& mask, const std::vector<cv::Point2f>& points) {
  if (points.empty()) return;
  std::vector<cv::Point2f> hull_f;
  cv::convexHull(points, hull_f);
  std::vector<cv::Point> hull;
  for (const auto& p : hull_f) hull.emplace_back(int(std::lround(p.x)), int(std::lround(p.y)));
  cv::fillConvexPoly(mask, hull, 255);
}

void fill_projected_hull(cv::Mat& mask, const scene::Camera& camera, const Eigen::Isometry3d& camera_to_world,
                         const std::vector<Eigen::Vector3d>& world) {
  std::vector<cv::Point2f> px;
  for (const auto& p : scene::project_clipped(camera, camera_to_world, world)) px.emplace_back(float(p.x()), float(p.y()));
  fill_convex_hull(mask, px);
}

}  // namespace chatsim::render
