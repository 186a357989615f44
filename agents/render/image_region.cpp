#include "agents/render/image_region.hpp"

#include <algorithm>
#include <cmath>

#include "common/scene/camera_model.hpp"

namespace chatsim::agents::render {

cv::Rect image_region(const std::vector<Eigen::Vector3d>& world, const scene::Camera& cam,
                      const Eigen::Isometry3d& camera_to_world, int pad_px) {
  const auto px = scene::project_clipped(cam, camera_to_world, world);
  if (px.empty()) return {};
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const auto& p : px) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
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
