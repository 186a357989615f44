#include "agents/render/image_region.hpp"

#include <algorithm>
#include <cmath>

namespace chatsim::agents::render {

cv::Rect image_region(const std::vector<Eigen::Vector3d>& world, const scene::Camera& cam,
                      const Eigen::Isometry3d& camera_to_world, int pad_px) {
  const double near = 0.1;
  const Eigen::Isometry3d w2c = camera_to_world.inverse();
  std::vector<Eigen::Vector3d> in_front, behind;
  for (const auto& w : world) {
    const Eigen::Vector3d c = w2c * w;
    (c.z() >= near ? in_front : behind).push_back(c);
  }
  if (in_front.empty()) return {};
  // The convex hull of the points, cut by the near plane, is the hull of these.
  std::vector<Eigen::Vector3d> clipped = in_front;
  for (const auto& a : in_front)
    for (const auto& b : behind) clipped.push_back(a + (b - a) * ((a.z() - near) / (a.z() - b.z())));
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const auto& c : clipped) {
    const double u = cam.fx * c.x() / c.z() + cam.cx, v = cam.fy * c.y() / c.z() + cam.cy;
    x0 = std::min(x0, u), x1 = std::max(x1, u), y0 = std::min(y0, v), y1 = std::max(y1, v);
  }
  // Clamped before rounding: near-plane points can project very far out.
  const double lim = 1e6;
  x0 = std::clamp(x0, -lim, lim), x1 = std::clamp(x1, -lim, lim), y0 = std::clamp(y0, -lim, lim), y1 = std::clamp(y1, -lim, lim);
  const cv::Rect padded(int(std::floor(x0)) - pad_px, int(std::floor(y0)) - pad_px, int(std::ceil(x1 - x0)) + 2 * pad_px,
                        int(std::ceil(y1 - y0)) + 2 * pad_px);
  return padded & cv::Rect(0, 0, cam.width, cam.height);
}

std::vector<cv::Rect> merge_overlapping(std::vector<cv::Rect> rects) {
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < rects.size() && !merged; ++i)
      for (size_t j = i + 1; j < rects.size() && !merged; ++j)
        if ((rects[i] & rects[j]).area() > 0) {
          rects[i] |= rects[j];
          rects.erase(rects.begin() + long(j));
          merged = true;
        }
  }
  return rects;
}

}  // namespace chatsim::agents::render
