#include "render/denoise.hpp"

#include <cmath>

#include "render/parallel.hpp"

namespace chatsim::render {

cv::Mat smooth_illumination(const cv::Mat& illum, const cv::Mat& normal, const cv::Mat& depth, const cv::Mat& valid,
                            const scene::Camera& cam, cv::Point origin, int iterations) {
  const int w = illum.cols, h = illum.rows;
  // Camera-frame positions of every pixel's surface point.
  cv::Mat pos(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float z = depth.at<float>(y, x);
      const float px = float((x + origin.x - cam.cx) / cam.fx), py = float((y + origin.y - cam.cy) / cam.fy);
      pos.at<cv::Vec3f>(y, x) = std::isfinite(z) ? cv::Vec3f(px * z, py * z, z) : cv::Vec3f(0, 0, 0);
    }
  static const float kernel[5] = {1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16};
  cv::Mat cur = illum.clone(), next(h, w, CV_32FC3);
  for (int it = 0; it < iterations; ++it) {
    const int step = 1 << it;
    parallel_for(h, [&](int y) {
      for (int x = 0; x < w; ++x) {
        if (!valid.at<uchar>(y, x)) {
          next.at<cv::Vec3f>(y, x) = cur.at<cv::Vec3f>(y, x);
          continue;
        }
        const cv::Vec3f n0 = normal.at<cv::Vec3f>(y, x);
        const cv::Vec3f p0 = pos.at<cv::Vec3f>(y, x);
        const float tolerance = 0.01f * p0[2] * float(step) + 0.01f;
        cv::Vec3f sum(0, 0, 0);
        float wsum = 0;
        for (int dy = -2; dy <= 2; ++dy) {
          const int yy = y + dy * step;
          if (yy < 0 || yy >= h) continue;
          for (int dx = -2; dx <= 2; ++dx) {
            const int xx = x + dx * step;
            if (xx < 0 || xx >= w || !valid.at<uchar>(yy, xx)) continue;
            const cv::Vec3f n1 = normal.at<cv::Vec3f>(yy, xx);
            const float nd = std::max(0.0f, n0.dot(n1));
            if (nd < 0.8f) continue;
            const float plane = std::abs(n0.dot(pos.at<cv::Vec3f>(yy, xx) - p0));
            const float wgt = kernel[dy + 2] * kernel[dx + 2] * std::pow(nd, 32.0f) * std::exp(-plane / tolerance);
            sum += cur.at<cv::Vec3f>(yy, xx) * wgt;
            wsum += wgt;
          }
        }
        next.at<cv::Vec3f>(y, x) = wsum > 0 ? sum / wsum : cur.at<cv::Vec3f>(y, x);
      }
    });
    std::swap(cur, next);
  }
  return cur;
}

}  // namespace chatsim::render
