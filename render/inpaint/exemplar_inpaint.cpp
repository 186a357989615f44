#include "render/inpaint/exemplar_inpaint.hpp"

#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

namespace chatsim::render::inpaint {

cv::Mat exemplar_inpaint(const cv::Mat& image, const cv::Mat& hole_in, const ExemplarOptions& o) {
  CV_Assert(image.type() == CV_32FC3 && hole_in.type() == CV_8UC1 && image.size() == hole_in.size());
  const int r = o.patch / 2, w = image.cols, h = image.rows;
  cv::Mat img = image.clone();
  cv::Mat hole = hole_in.clone();
  cv::Mat conf(h, w, CV_32F);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) conf.at<float>(y, x) = hole.at<uchar>(y, x) ? 0.0f : 1.0f;
  // Source patch centres: patches entirely known (fixed from the start).
  cv::Mat known_patch(h, w, CV_8U, cv::Scalar(0));
  {
    cv::Mat eroded;
    cv::Mat known = hole == 0;
    cv::erode(known, eroded, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(o.patch, o.patch)));
    eroded.copyTo(known_patch);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (y < r || x < r || y >= h - r || x >= w - r) known_patch.at<uchar>(y, x) = 0;
  }
  std::vector<cv::Point> sources;
  for (int y = r; y < h - r; ++y)
    for (int x = r; x < w - r; ++x)
      if (known_patch.at<uchar>(y, x)) sources.emplace_back(x, y);
  if (sources.empty()) {
    // Nothing to copy from: fall back to diffusion.
    cv::Mat u8, out8;
    cv::Mat scaled;
    double mx = 0;
    cv::minMaxLoc(img.reshape(1), nullptr, &mx);
    img.convertTo(u8, CV_8UC3, mx > 0 ? 255.0 / mx : 1.0);
    cv::inpaint(u8, hole_in, out8, 3, cv::INPAINT_TELEA);
    out8.convertTo(scaled, CV_32FC3, mx > 0 ? mx / 255.0 : 1.0);
    return scaled;
  }
  cv::Mat gray;
  int remaining = cv::countNonZero(hole);
  int guard = 0;
  while (remaining > 0 && guard++ < w * h) {
    cv::cvtColor(img, gray, cv::COLOR_RGB2GRAY);
    cv::Mat gx, gy;
    cv::Scharr(gray, gx, CV_32F, 1, 0);
    cv::Scharr(gray, gy, CV_32F, 0, 1);
    cv::Mat mask_f;
    hole.convertTo(mask_f, CV_32F, 1.0 / 255);
    cv::Mat nx, ny;
    cv::Sobel(mask_f, nx, CV_32F, 1, 0);
    cv::Sobel(mask_f, ny, CV_32F, 0, 1);
    // The fill front: hole pixels next to known ones; take the highest priority.
    cv::Mat dil;
    cv::dilate(hole == 0, dil, cv::Mat());
    float best_p = -1;
    cv::Point target(-1, -1);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!hole.at<uchar>(y, x) || !dil.at<uchar>(y, x)) continue;
        float c = 0;
        int n = 0;
        for (int dy = -r; dy <= r; ++dy)
          for (int dx = -r; dx <= r; ++dx) {
            const int yy = y + dy, xx = x + dx;
            if (yy < 0 || xx < 0 || yy >= h || xx >= w) continue;
            c += conf.at<float>(yy, xx);
            ++n;
          }
        c /= float(n);
        // Isophote (gradient turned 90 degrees) against the front's normal; strongest nearby.
        float d = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int yy = std::clamp(y + dy, 0, h - 1), xx = std::clamp(x + dx, 0, w - 1);
            if (hole.at<uchar>(yy, xx)) continue;
            const float ix = -gy.at<float>(yy, xx), iy = gx.at<float>(yy, xx);
            const float mn = std::hypot(nx.at<float>(y, x), ny.at<float>(y, x)) + 1e-6f;
            d = std::max(d, std::abs(ix * nx.at<float>(y, x) + iy * ny.at<float>(y, x)) / mn);
          }
        const float p = c * (d / 16.0f + 0.001f);
        if (p > best_p) best_p = p, target = {x, y};
      }
    if (target.x < 0) break;
    // The most similar fully known patch (sum of squared differences over the known pixels).
    double best = std::numeric_limits<double>::max();
    cv::Point src(-1, -1);
    for (const auto& s : sources) {
      if (o.search_radius > 0 && (std::abs(s.x - target.x) > o.search_radius || std::abs(s.y - target.y) > o.search_radius)) continue;
      double ssd = 0;
      for (int dy = -r; dy <= r && ssd < best; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int ty = target.y + dy, tx = target.x + dx;
          if (ty < 0 || tx < 0 || ty >= h || tx >= w || hole.at<uchar>(ty, tx)) continue;
          const cv::Vec3f a = img.at<cv::Vec3f>(ty, tx), b = img.at<cv::Vec3f>(s.y + dy, s.x + dx);
          const cv::Vec3f dd = a - b;
          ssd += double(dd.dot(dd));
        }
      if (ssd < best) best = ssd, src = s;
    }
    if (src.x < 0) {  // no source within reach: the nearest one anywhere
      double dmin = std::numeric_limits<double>::max();
      for (const auto& s : sources) {
        const double dd = std::hypot(s.x - target.x, s.y - target.y);
        if (dd < dmin) dmin = dd, src = s;
      }
    }
    const float c_target = [&] {
      float c = 0;
      int n = 0;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int yy = target.y + dy, xx = target.x + dx;
          if (yy < 0 || xx < 0 || yy >= h || xx >= w) continue;
          c += conf.at<float>(yy, xx);
          ++n;
        }
      return c / float(n);
    }();
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int ty = target.y + dy, tx = target.x + dx;
        if (ty < 0 || tx < 0 || ty >= h || tx >= w || !hole.at<uchar>(ty, tx)) continue;
        img.at<cv::Vec3f>(ty, tx) = img.at<cv::Vec3f>(src.y + dy, src.x + dx);
        hole.at<uchar>(ty, tx) = 0;
        conf.at<float>(ty, tx) = c_target;
        --remaining;
      }
  }
  return img;
}

}  // namespace chatsim::render::inpaint
