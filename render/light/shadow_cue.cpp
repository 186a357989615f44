#include "render/light/shadow_cue.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"
#include "common/scene/objects.hpp"

namespace chatsim::render::light {
namespace {


// The ground region a box's shadow covers for a sun direction (one convex image polygon per
// solid casting it), and the box itself; false when the box is far from the camera or out of view.
struct ShadowPolygons {
  std::vector<std::vector<cv::Point>> shadow;
  std::vector<cv::Point> body;
};
cv::Rect bounds(const std::vector<std::vector<cv::Point>>& polygons) {
  cv::Rect r;
  for (const auto& p : polygons) r = r.area() == 0 ? cv::boundingRect(p) : (r | cv::boundingRect(p));
  return r;
}
bool shadow_region(const LightView& v, const GroundBox& b, const Eigen::Vector3d& sun, ShadowPolygons& out) {
  if ((b.center - v.camera_to_world.translation()).norm() > 30) return false;
  const double ground = b.center.z() - b.size_lwh.z() / 2;
  const auto corners = scene::box_corners(b.center, b.size_lwh, b.yaw);
  // Clipped at the near plane: the nearest vehicles, reaching past the image, cast the largest
  // visible shadows.
  auto pixels = [&](const std::vector<Eigen::Vector3d>& world) {
    std::vector<cv::Point> px, hull;
    for (const auto& p : scene::project_clipped(v.camera, v.camera_to_world, world, 0.5))
      px.emplace_back(int(std::lround(p.x())), int(std::lround(p.y())));
    if (px.size() >= 3) cv::convexHull(px, hull);
    return hull;
  };
  out.shadow.clear();
  for (const auto& solid : shadow_casters(b)) {
    std::vector<Eigen::Vector3d> on_ground;
    for (const auto& c : solid) {
      const Eigen::Vector3d tip = c - sun * ((c.z() - ground) / sun.z());
      on_ground.emplace_back(tip.x(), tip.y(), ground);
      on_ground.emplace_back(c.x(), c.y(), ground);
    }
    auto hull = pixels(on_ground);
    if (hull.size() >= 3) out.shadow.push_back(std::move(hull));
  }
  out.body = pixels(std::vector<Eigen::Vector3d>(corners.begin(), corners.end()));
  if (out.shadow.empty() || out.body.size() < 3) return false;
  return (bounds(out.shadow) & cv::Rect(0, 0, v.camera.width, v.camera.height)).area() >= 50;
}

// Rasterises convex polygons (their union) into a mask covering only `roi` of the image.
cv::Mat roi_mask(const cv::Rect& roi, const std::vector<std::vector<cv::Point>>& polygons) {
  cv::Mat m(roi.size(), CV_8U, cv::Scalar(0));
  for (const auto& polygon : polygons)
    if (!polygon.empty()) cv::fillPoly(m, std::vector<std::vector<cv::Point>>{polygon}, 255, cv::LINE_8, 0, -roi.tl());
  return m;
}

// How well a predicted shadow's outline matches the dark ground around a box: the share of the
// predicted shadow that is dark times the share of the ground just around it that is lit.
// Without it, a direction whose shadow covers the real one and much lit ground besides, or a
// sliver of it, scores as well as the right one (seen from a car, the visible strip of many
// shadow directions' outlines is the same). Dark and lit split at the geometric mean of the
// surroundings' bright end and the predicted shadow's level; 0 without such contrast.
double outline_agreement(const cv::Mat& g, const cv::Mat& below_horizon, const cv::Mat& shadow, const cv::Mat& ring, const cv::Mat& blocked,
                          float dark) {
  // The ground: below the horizon and not the box.
  thread_local std::vector<float> ground;
  ground.clear();
  for (int y = 0; y < g.rows; y += 2) {
    const uchar *b = below_horizon.ptr<uchar>(y), *k = blocked.ptr<uchar>(y);
    const float* l = g.ptr<float>(y);
    for (int x = 0; x < g.cols; x += 2)
      if (b[x] && !k[x]) ground.push_back(l[x]);
  }
  if (ground.size() < 30) return 0;
  std::nth_element(ground.begin(), ground.begin() + long(ground.size() * 8 / 10), ground.end());
  const float lit = ground[ground.size() * 8 / 10];
  if (lit < 1.5f * dark) return 0;
  const float split = std::sqrt(lit * dark);
  long in_dark = 0, in_n = 0, around_lit = 0, around_n = 0;
  for (int y = 0; y < g.rows; ++y) {
    const uchar *b = below_horizon.ptr<uchar>(y), *k = blocked.ptr<uchar>(y), *sh = shadow.ptr<uchar>(y), *r = ring.ptr<uchar>(y);
    const float* l = g.ptr<float>(y);
    for (int x = 0; x < g.cols; ++x) {
      if (!b[x] || k[x]) continue;
      const bool d = l[x] < split;
      if (sh[x]) ++in_n, in_dark += d;
      else if (r[x]) ++around_n, around_lit += !d;
    }
  }
  if (in_n == 0 || around_n == 0) return 0;
  return double(in_dark) / double(in_n) * double(around_lit) / double(around_n);
}

}  // namespace

ShadowCue shadow_cue(const std::vector<LightView>& views, const std::vector<cv::Mat>& gray, const std::vector<cv::Mat>& below,
                     const std::vector<GroundBox>& boxes, const Eigen::Vector3d& sun, int instants) {
  ShadowCue cue;
  if (sun.z() < 0.08) return cue;
  constexpr int kRing = 15;  // pixels of ground around the shadow
  const Eigen::Vector3d mirror(-sun.x(), -sun.y(), sun.z());
  std::vector<double> logs, contrasts, ratios;
  for (const auto& b : boxes)
    for (size_t vi = 0; vi < views.size(); ++vi) {
      if (b.frame >= 0 && views[vi].frame >= 0 && b.frame != views[vi].frame) continue;
      const cv::Rect image(0, 0, views[vi].camera.width, views[vi].camera.height);
      ShadowPolygons sp, mp;
      if (!shadow_region(views[vi], b, sun, sp)) continue;
      const bool mirrored = shadow_region(views[vi], b, mirror, mp);
      cv::Rect box = bounds(sp.shadow) | cv::boundingRect(sp.body);
      if (mirrored) box |= bounds(mp.shadow);
      box.x -= kRing, box.y -= kRing, box.width += 2 * kRing, box.height += 2 * kRing;
      const cv::Rect roi = box & image;
      if (roi.area() == 0) continue;
      cv::Mat shadow = roi_mask(roi, sp.shadow), blocked = roi_mask(roi, {sp.body}), lit, ring;
      cv::dilate(blocked, blocked, cv::Mat(), cv::Point(-1, -1), 2);
      if (mirrored) {
        lit = roi_mask(roi, mp.shadow);
        const cv::Mat overlap = shadow & lit;
        shadow.setTo(0, blocked | overlap);
        lit.setTo(0, blocked | overlap);
      } else {
        shadow.setTo(0, blocked);
      }
      cv::dilate(shadow, ring, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * kRing + 1, 2 * kRing + 1)));  // a square: separable, fast
      ring.setTo(0, blocked | shadow);
      const cv::Mat g = gray[vi](roi);
      // The three medians from one pass, with buffers kept per thread: this runs for every
      // box, view and candidate sun.
      thread_local std::vector<float> in_v, around_v, side_v;
      in_v.clear(), around_v.clear(), side_v.clear();
      for (int y = 0; y < roi.height; ++y) {
        const uchar *sh = shadow.ptr<uchar>(y), *r = ring.ptr<uchar>(y), *li = mirrored ? lit.ptr<uchar>(y) : nullptr;
        const float* l = g.ptr<float>(y);
        for (int x = 0; x < roi.width; ++x) {
          if (sh[x]) in_v.push_back(l[x]);
          if (r[x]) around_v.push_back(l[x]);
          if (li && li[x]) side_v.push_back(l[x]);
        }
      }
      auto median_of = [](std::vector<float>& v) {
        if (v.size() < 30) return -1.0f;
        std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
        return v[v.size() / 2];
      };
      const float in = median_of(in_v), around = median_of(around_v), other_side = mirrored ? median_of(side_v) : -1.0f;
      if (in < 0 || around < 0) continue;
      // A shadow is darker than the ground just around it (it has edges: a direction whose
      // shadow covers only a sliver of a real one is not) and, where that side is in view,
      // than the ground on the other side of the vehicle (the light the vehicle hides from the
      // sky cancels out).
      double r = (around + 1e-4) / (in + 1e-4);
      if (other_side >= 0) r = std::min(r, (other_side + 1e-4) / (in + 1e-4));
      // Capped at a ratio of 4 (a real car shadow under a clear sky is 2-4 times darker), then
      // weighed by how well the outline fits.
      const double l = std::min(std::log(std::max(r, 1e-3)), std::log(4.0));
      contrasts.push_back(l);
      logs.push_back(l * outline_agreement(g, below[vi](roi), shadow, ring, blocked, in));
      ratios.push_back(r);
    }
  if (logs.empty()) return cue;
  cue.boxes = int(logs.size());
  // Each measured vehicle adds its (capped) evidence: a sun direction that explains the shadows
  // of many vehicles beats one whose shadow lands on a single dark patch, as a mean would not.
  for (double l : logs) cue.evidence += l;
  for (double c : contrasts) cue.score += c / double(contrasts.size());
  cue.evidence /= double(instants);  // several instants weigh as one against the sky fit
  std::nth_element(ratios.begin(), ratios.begin() + long(ratios.size() / 2), ratios.end());
  cue.ratio = ratios[ratios.size() / 2];
  return cue;
}

}  // namespace chatsim::render::light
