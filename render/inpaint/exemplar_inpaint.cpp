#include "render/inpaint/exemplar_inpaint.hpp"

#include <cmath>
#include <limits>
#include <queue>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

namespace chatsim::render::inpaint {

cv::Mat exemplar_inpaint(const cv::Mat& image, const cv::Mat& hole_in, const ExemplarOptions& o, const cv::Mat& no_source) {
  CV_Assert(image.type() == CV_32FC3 && hole_in.type() == CV_8UC1 && image.size() == hole_in.size());
  CV_Assert(no_source.empty() || (no_source.type() == CV_8UC1 && no_source.size() == image.size()));
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
    if (!no_source.empty()) known &= no_source == 0;
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
  // Gradients, hole normals and fill priorities are kept up to date locally after each
  // pasted patch: only the pixels near it change (the result is the same as recomputing
  // everything each step, at a fraction of the cost).
  cv::Mat gray, gx, gy, mask_f, nx, ny;
  cv::cvtColor(img, gray, cv::COLOR_RGB2GRAY);
  hole.convertTo(mask_f, CV_32F, 1.0 / 255);
  auto refresh_gradients = [&](const cv::Rect& area) {
    const cv::Rect a = area & cv::Rect(0, 0, w, h);
    if (a.empty()) return;
    cv::Mat tmp;
    cv::cvtColor(img(a), tmp, cv::COLOR_RGB2GRAY);
    tmp.copyTo(gray(a));
    hole(a).convertTo(tmp, CV_32F, 1.0 / 255);
    tmp.copyTo(mask_f(a));
    // Filters on a sub-matrix read the real neighbours outside it.
    const cv::Rect g = cv::Rect(a.x - 1, a.y - 1, a.width + 2, a.height + 2) & cv::Rect(0, 0, w, h);
    cv::Scharr(gray(g), tmp, CV_32F, 1, 0), tmp.copyTo(gx(g));
    cv::Scharr(gray(g), tmp, CV_32F, 0, 1), tmp.copyTo(gy(g));
    cv::Sobel(mask_f(g), tmp, CV_32F, 1, 0), tmp.copyTo(nx(g));
    cv::Sobel(mask_f(g), tmp, CV_32F, 0, 1), tmp.copyTo(ny(g));
  };
  gx.create(h, w, CV_32F), gy.create(h, w, CV_32F), nx.create(h, w, CV_32F), ny.create(h, w, CV_32F);
  cv::Scharr(gray, gx, CV_32F, 1, 0);
  cv::Scharr(gray, gy, CV_32F, 0, 1);
  cv::Sobel(mask_f, nx, CV_32F, 1, 0);
  cv::Sobel(mask_f, ny, CV_32F, 0, 1);
  // Priority of a pixel on the fill front (a hole pixel next to a known one); -1 elsewhere.
  auto priority_at = [&](int x, int y) {
    if (!hole.at<uchar>(y, x)) return -1.0f;
    bool front = false;
    for (int dy = -1; dy <= 1 && !front; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int yy = y + dy, xx = x + dx;
        if (yy >= 0 && xx >= 0 && yy < h && xx < w && !hole.at<uchar>(yy, xx)) {
          front = true;
          break;
        }
      }
    if (!front) return -1.0f;
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
    return c * (d / 16.0f + 0.001f);
  };
  // Priorities live in a map; a heap of (priority, row, column) entries finds the highest (the
  // first in row order on ties), skipping entries a later refresh made stale.
  cv::Mat prio(h, w, CV_32F, cv::Scalar(-1));
  struct Entry {
    float p;
    int y, x;
    bool operator<(const Entry& o) const { return p != o.p ? p < o.p : (y != o.y ? y > o.y : x > o.x); }
  };
  std::priority_queue<Entry> heap;
  auto refresh_priorities = [&](const cv::Rect& area) {
    const cv::Rect a = area & cv::Rect(0, 0, w, h);
    for (int y = a.y; y < a.y + a.height; ++y)
      for (int x = a.x; x < a.x + a.width; ++x) {
        const float p = priority_at(x, y);
        prio.at<float>(y, x) = p;
        if (p >= 0) heap.push({p, y, x});
      }
  };
  refresh_priorities(cv::Rect(0, 0, w, h));
  // The nearest source patch of every pixel, for targets with none within the search radius.
  cv::Mat nearest_label;
  std::vector<cv::Point> label_point;
  auto nearest_source = [&](cv::Point t) {
    if (nearest_label.empty()) {
      cv::Mat dist;
      cv::distanceTransform(known_patch == 0, dist, nearest_label, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
      for (const auto& s : sources) {
        const int l = nearest_label.at<int>(s.y, s.x);
        if (l >= int(label_point.size())) label_point.resize(size_t(l) + 1, s);
        label_point[size_t(l)] = s;
      }
    }
    return label_point[size_t(nearest_label.at<int>(t.y, t.x))];
  };
  const int reach = o.search_radius > 0 ? o.search_radius : std::max(w, h);
  int remaining = cv::countNonZero(hole);
  int guard = 0;
  while (remaining > 0 && guard++ < w * h) {
    cv::Point target(-1, -1);
    while (!heap.empty()) {
      const Entry e = heap.top();
      heap.pop();
      if (prio.at<float>(e.y, e.x) == e.p) {
        target = {e.x, e.y};
        break;
      }
    }
    if (target.x < 0) break;
    // The most similar fully known patch within reach (sum of squared differences over the
    // known pixels), in row order.
    double best = std::numeric_limits<double>::max();
    cv::Point src(-1, -1);
    for (int sy = std::max(r, target.y - reach); sy <= std::min(h - r - 1, target.y + reach); ++sy)
      for (int sx = std::max(r, target.x - reach); sx <= std::min(w - r - 1, target.x + reach); ++sx) {
        if (!known_patch.at<uchar>(sy, sx)) continue;
        if (o.beside_slope > 0 && std::abs(sy - target.y) > r + o.beside_slope * std::abs(sx - target.x)) continue;
        double ssd = 0;
        for (int dy = -r; dy <= r && ssd < best; ++dy)
          for (int dx = -r; dx <= r; ++dx) {
            const int ty = target.y + dy, tx = target.x + dx;
            if (ty < 0 || tx < 0 || ty >= h || tx >= w || hole.at<uchar>(ty, tx)) continue;
            const cv::Vec3f a = img.at<cv::Vec3f>(ty, tx), b = img.at<cv::Vec3f>(sy + dy, sx + dx);
            const cv::Vec3f dd = a - b;
            ssd += double(dd.dot(dd));
          }
        if (ssd < best) best = ssd, src = {sx, sy};
      }
    if (src.x < 0) src = nearest_source(target);  // no source within reach: the nearest one
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
    const cv::Rect patch(target.x - r, target.y - r, o.patch, o.patch);
    refresh_gradients(cv::Rect(patch.x - 2, patch.y - 2, patch.width + 4, patch.height + 4));
    refresh_priorities(cv::Rect(patch.x - r - 2, patch.y - r - 2, patch.width + 2 * r + 4, patch.height + 2 * r + 4));
  }
  return img;
}

}  // namespace chatsim::render::inpaint
