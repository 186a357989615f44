#include "render/inpaint/deletion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

#include "common/scene/camera_model.hpp"
#include "common/scene/objects.hpp"
#include "render/gs/model.hpp"
#include "render/image_io.hpp"
#include "render/inpaint/exemplar_inpaint.hpp"
#include "render/inpaint/seam_blend.hpp"
#include "render/projected_hull.hpp"

namespace chatsim::render::inpaint {
namespace {

// The ground polygon an object's box and shadow can darken: footprint, padded, stretched away
// from the sun.
std::vector<Eigen::Vector3d> ground_outline(const scene::TrackPoint& p, const Eigen::Vector3d& size, const DeletionOptions& o) {
  std::vector<Eigen::Vector3d> pts;
  const double ground = p.center.z() - size.z() / 2;
  const Eigen::Vector3d pad(size.x() + 2 * o.margin_m, size.y() + 2 * o.margin_m, size.z());
  for (const auto& c : scene::box_corners(p.center, pad, p.yaw)) pts.emplace_back(c.x(), c.y(), ground);
  if (o.sun_direction && o.sun_direction->z() > 0.1) {
    const Eigen::Vector3d s = o.sun_direction->normalized();
    for (const auto& c : scene::box_corners(p.center, size, p.yaw)) {
      const Eigen::Vector3d g = c - s * ((c.z() - ground) / s.z());
      pts.emplace_back(g.x(), g.y(), ground);
    }
  }
  return pts;
}

std::optional<scene::TrackPoint> at_time(const scene::Scene& s, const scene::ObjectTrack& o, double t) {
  const auto pose = gs::object_pose(s, o, t);
  if (!pose) return std::nullopt;
  scene::TrackPoint p;
  p.center = pose->translation();
  p.yaw = std::atan2(pose->linear()(1, 0), pose->linear()(0, 0));
  return p;
}

// Fills the image area of the convex hull of world points (clipped at the near plane), dilated
// by `pad` pixels.
void fill_projected(cv::Mat& mask, const DeletionImage& im, const std::vector<Eigen::Vector3d>& pts, int pad) {
  cv::Mat m(mask.size(), CV_8U, cv::Scalar(0));
  fill_projected_hull(m, im.cam, im.pose, pts);
  if (pad > 0) cv::dilate(m, m, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * pad + 1, 2 * pad + 1)));
  mask |= m;
}

cv::Vec3f bilinear(const cv::Mat& img, double x, double y) {
  const int x0 = std::clamp(int(std::floor(x)), 0, img.cols - 1), y0 = std::clamp(int(std::floor(y)), 0, img.rows - 1);
  const int x1 = std::min(x0 + 1, img.cols - 1), y1 = std::min(y0 + 1, img.rows - 1);
  const float ax = float(std::clamp(x - x0, 0.0, 1.0)), ay = float(std::clamp(y - y0, 0.0, 1.0));
  return (img.at<cv::Vec3f>(y0, x0) * (1 - ax) + img.at<cv::Vec3f>(y0, x1) * ax) * (1 - ay) +
         (img.at<cv::Vec3f>(y1, x0) * (1 - ax) + img.at<cv::Vec3f>(y1, x1) * ax) * ay;
}

// The ground map of one object: world rectangle, cells, what was seen.
struct GroundMap {
  double x0 = 0, y0 = 0, res = 0.04, z = 0;
  cv::Mat radiance;  // CV_32FC3
  cv::Mat seen;      // CV_8UC1
  cv::Mat valid;     // CV_8UC1: seen, or filled from what was seen
  cv::Mat path;      // CV_8UC1: the ground the object and its shadow covered at some time
  bool contains(double x, double y) const { return at(valid, x, y); }
  bool on_path(double x, double y) const { return at(path, x, y) && contains(x, y); }

 private:
  bool at(const cv::Mat& cells, double x, double y) const {
    const double u = (x - x0) / res, v = (y - y0) / res;
    return u >= 0 && v >= 0 && u < radiance.cols - 1 && v < radiance.rows - 1 && cells.at<uchar>(int(v + 0.5), int(u + 0.5)) != 0;
  }
};

// Where an object itself stands (its box, barely padded, no shadow).
DeletionOptions tight_outline(DeletionOptions o) {
  o.margin_m = 0.2;
  o.sun_direction.reset();
  return o;
}

// Marks the pixels of a rendered view, not yet masked, whose surface is the ground on a deleted
// object's path (the field's depth agrees with the ground there), as that object's. Small islands
// inside that ground where the depth disagrees are the field's floaters along the path (what it
// learned of the moving object near the road), not something standing there: they go too. A
// labelled object that stays (`keep`) is never painted over, even where its foot is as far as
// the ground behind it.
void add_path_pixels(const DeletionImage& im, const std::vector<GroundMap>& maps, const cv::Mat& keep, cv::Mat& mask, cv::Mat& owner) {
  const Eigen::Matrix3d R = im.pose.linear();
  const Eigen::Vector3d C = im.pose.translation();
  cv::Mat on_path(mask.size(), CV_8U, cv::Scalar(0)), agrees(mask.size(), CV_8U, cv::Scalar(0));
  cv::Mat path_owner(mask.size(), CV_32S, cv::Scalar(-1));
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) {
      if (mask.at<uchar>(y, x)) continue;
      // A ray with unit camera z: the distance along it to the ground is the ground's z-depth.
      const Eigen::Vector3d d = R * Eigen::Vector3d((x - im.cam.cx) / im.cam.fx, (y - im.cam.cy) / im.cam.fy, 1);
      if (d.z() > -1e-6) continue;
      const float z = im.rendered_depth.at<float>(y, x);
      for (size_t m = 0; m < maps.size(); ++m) {
        const double t = (maps[m].z - C.z()) / d.z();
        if (t <= 0) continue;
        const Eigen::Vector3d p = C + t * d;
        if (!maps[m].on_path(p.x(), p.y())) continue;
        on_path.at<uchar>(y, x) = 255;
        path_owner.at<int>(y, x) = int(m);
        if (std::isfinite(z) && std::abs(t - z) <= 0.05 * t + 0.3) agrees.at<uchar>(y, x) = 255;
        break;
      }
    }
  cv::Mat islands = on_path & ~agrees & ~keep, labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(islands, labels, stats, centroids, 8, CV_32S);
  // An island touches something off the path (or kept) when it does not lie inside the path.
  std::vector<uint8_t> enclosed(size_t(n), 1);
  cv::Mat beyond;
  cv::dilate(~on_path | keep | mask, beyond, cv::Mat());
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x)
      if (const int l = labels.at<int>(y, x); l > 0 && beyond.at<uchar>(y, x)) enclosed[size_t(l)] = 0;
  const int max_area = mask.rows * mask.cols / 50;
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x) {
      const int l = labels.at<int>(y, x);
      const bool island = l > 0 && enclosed[size_t(l)] && stats.at<int>(l, cv::CC_STAT_AREA) <= max_area;
      if ((!agrees.at<uchar>(y, x) && !island) || keep.at<uchar>(y, x)) continue;
      mask.at<uchar>(y, x) = 255;
      owner.at<int>(y, x) = path_owner.at<int>(y, x);
    }
}

// Along a removed car's path in a rendered view, the ground map replaces the field's render only
// where the two differ by more than softness and the captures' noise do (the smeared shadow,
// ghosts, in brightness or in colour): elsewhere the field's smooth render is the closer of the
// two (measured on the demo's shifted truth views, `eval deletion --moved-views`). Those pixels
// leave the mask.
void keep_unghosted_ground(const cv::Mat& render, const cv::Mat& path, double min_log_step, cv::Mat& filled, cv::Mat& mask) {
  constexpr double kSigmaPx = 3;
  // Per channel: the log radiance, smoothed over the path only.
  const auto level = [&](const cv::Mat& rgb) {
    cv::Mat lg;
    cv::log(cv::max(rgb, 1e-4), lg);
    return mean_over_mask(lg, path, kSigmaPx);
  };
  const cv::Mat a = level(render), b = level(filled);
  for (int y = 0; y < path.rows; ++y)
    for (int x = 0; x < path.cols; ++x) {
      if (!path.at<uchar>(y, x)) continue;
      const cv::Vec3f d = a.at<cv::Vec3f>(y, x) - b.at<cv::Vec3f>(y, x);
      if (std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])}) >= min_log_step) continue;
      mask.at<uchar>(y, x) = 0;
      filled.at<cv::Vec3f>(y, x) = render.at<cv::Vec3f>(y, x);
    }
}

// Distance along a ray to where it enters an oriented box (nullopt: it misses).
std::optional<double> ray_box_entry(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, const scene::TrackPoint& p,
                                    const Eigen::Vector3d& size) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(p.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d o = R.transpose() * (origin - p.center), d = R.transpose() * dir;
  double t0 = 0, t1 = 1e30;
  for (int k = 0; k < 3; ++k) {
    const double h = size[k] / 2;
    if (std::abs(d[k]) < 1e-12) {
      if (std::abs(o[k]) > h) return std::nullopt;
      continue;
    }
    double a = (-h - o[k]) / d[k], b = (h - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
    if (t0 > t1) return std::nullopt;
  }
  return t0;
}

// Where labelled objects that are not deleted stand in front of a deleted one: those pixels
// show the nearer object, which stays (a car hidden behind a truck leaves the truck alone).
// Per pixel of `region`: the ray's entry into each other box against its entry into the
// deleted box, or against the ground below it where the ray misses the box (its shadow).
cv::Mat nearer_objects_mask(const scene::Scene& s, const DeletionImage& im, const scene::ObjectTrack& deleted,
                            const std::vector<std::string>& ids, const cv::Mat& region) {
  cv::Mat mask(im.cam.height, im.cam.width, CV_8U, cv::Scalar(0));
  const auto p = at_time(s, deleted, im.time);
  if (!p) return mask;
  const cv::Rect bounds = cv::boundingRect(region);
  if (bounds.empty()) return mask;
  // Candidates: other objects whose image footprint meets the region's bounds.
  std::vector<std::pair<scene::TrackPoint, Eigen::Vector3d>> others;
  const Eigen::Isometry3d w2c = im.pose.inverse();
  for (const auto& other : s.objects) {
    if (std::find(ids.begin(), ids.end(), other.id) != ids.end()) continue;
    const auto q = at_time(s, other, im.time);
    if (!q) continue;
    // The image rectangle its corners span (a box reaching behind the camera counts as anywhere).
    double u0 = 1e30, v0 = 1e30, u1 = -1e30, v1 = -1e30;
    bool behind = false, front = false;
    for (const auto& c : scene::box_corners(q->center, other.size_lwh, q->yaw)) {
      const Eigen::Vector3d k = w2c * c;
      if (k.z() < 0.1) {
        behind = true;
        continue;
      }
      front = true;
      const double u = im.cam.fx * k.x() / k.z() + im.cam.cx, v = im.cam.fy * k.y() / k.z() + im.cam.cy;
      u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
    }
    if (!front) continue;
    if (!behind && (u1 < bounds.x || v1 < bounds.y || u0 > bounds.x + bounds.width || v0 > bounds.y + bounds.height)) continue;
    others.emplace_back(*q, other.size_lwh);
  }
  if (others.empty()) return mask;
  const Eigen::Vector3d C = im.pose.translation();
  const Eigen::Matrix3d R = im.pose.linear();
  const double ground = p->center.z() - deleted.size_lwh.z() / 2;
  for (int y = bounds.y; y < bounds.y + bounds.height; ++y)
    for (int x = bounds.x; x < bounds.x + bounds.width; ++x) {
      if (!region.at<uchar>(y, x)) continue;
      const Eigen::Vector3d d = (R * Eigen::Vector3d((x - im.cam.cx) / im.cam.fx, (y - im.cam.cy) / im.cam.fy, 1)).normalized();
      double t = 1e30;
      if (const auto e = ray_box_entry(C, d, *p, deleted.size_lwh)) t = *e;
      else if (d.z() < -1e-9) t = (ground - C.z()) / d.z();
      for (const auto& [q, size] : others)
        if (const auto e = ray_box_entry(C, d, q, size); e && *e < t) {
          mask.at<uchar>(y, x) = 255;
          break;
        }
    }
  return mask;
}

// The share of the hole's pixels whose ray meets a deleted object's box, where the field's
// surface (its z-depth without the objects) lies in front of that box: what the field renders
// there is no background behind the object but the object itself, learned a few metres off its
// box where the capture's views do not pin its depth (or floaters before it). Boxes farther than
// `max_distance` (along the ray) do not count. The depth is z-depth within 3 % (0.5 m at least).
double share_in_front_of_boxes(const scene::Scene& s, const DeletionImage& im, const std::vector<std::string>& ids, const cv::Mat& hole,
                               const cv::Mat& depth, double max_distance, int step) {
  std::vector<std::pair<scene::TrackPoint, Eigen::Vector3d>> boxes;
  for (const auto& id : ids)
    if (const auto* obj = s.object(id))
      if (const auto q = at_time(s, *obj, im.time)) boxes.emplace_back(*q, obj->size_lwh);
  const Eigen::Matrix3d R = im.pose.linear();
  const Eigen::Vector3d C = im.pose.translation();
  int hit = 0, in_front = 0;
  for (int y = 0; y < hole.rows; y += step)
    for (int x = 0; x < hole.cols; x += step) {
      if (!hole.at<uchar>(y, x)) continue;
      // A ray with unit camera z: distances along it are z-depths.
      const Eigen::Vector3d d = R * Eigen::Vector3d((x - im.cam.cx) / im.cam.fx, (y - im.cam.cy) / im.cam.fy, 1);
      double entry = 1e30;
      for (const auto& [q, size] : boxes)
        if (const auto e = ray_box_entry(C, d, q, size)) entry = std::min(entry, *e);
      if (entry >= 1e30 || entry > max_distance) continue;
      ++hit;
      const float z = depth.at<float>(y, x);
      // 0: outside what was rendered (render_region), no surface known there.
      if (std::isfinite(z) && z > 0 && z < entry - std::max(0.5, 0.03 * entry)) ++in_front;
    }
  return hit > 0 ? double(in_front) / hit : 0;
}

}  // namespace

cv::Mat deletion_mask(const scene::Scene& s, const DeletionImage& im, const std::vector<std::string>& ids, const DeletionOptions& o) {
  cv::Mat mask(im.cam.height, im.cam.width, CV_8U, cv::Scalar(0));
  for (const auto& id : ids) {
    const auto* obj = s.object(id);
    if (obj == nullptr) continue;
    const auto p = at_time(s, *obj, im.time);
    if (!p) continue;
    std::vector<Eigen::Vector3d> pts;
    for (const auto& c : scene::box_corners(p->center, obj->size_lwh, p->yaw)) pts.push_back(c);
    const auto g = ground_outline(*p, obj->size_lwh, o);
    fill_projected(mask, im, pts, o.box_pad_px);
    fill_projected(mask, im, g, 0);
  }
  return mask;
}

DeletionStats delete_objects(const scene::Scene& s, const std::vector<std::string>& ids, std::vector<DeletionImage>& targets,
                             const std::vector<DeletionImage>& sources, const DeletionOptions& o, const BackgroundRenderer& background) {
  const auto t0 = std::chrono::steady_clock::now();
  DeletionStats stats;
  // Where every labelled object hides the ground in each source image (no view of the ground
  // through a car); the deleted ones also with their shadows.
  std::vector<std::string> all_ids;
  for (const auto& obj : s.objects) all_ids.push_back(obj.id);
  std::vector<std::string> others;
  for (const auto& id : all_ids)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) others.push_back(id);
  std::vector<cv::Mat> occluded(sources.size());
  for (size_t i = 0; i < sources.size(); ++i) {
    occluded[i] = deletion_mask(s, sources[i], all_ids, tight_outline(o)) | deletion_mask(s, sources[i], ids, o);
  }
  // One ground map per deleted object, over its whole track.
  std::vector<GroundMap> maps;
  double seen_cells = 0, all_cells = 0;
  for (const auto& id : ids) {
    const auto* obj = s.object(id);
    if (obj == nullptr || obj->track.empty()) continue;
    double xmin = 1e18, ymin = 1e18, xmax = -1e18, ymax = -1e18, zmin = 1e18;
    for (const auto& tp : obj->track)
      for (const auto& c : ground_outline(tp, obj->size_lwh, o)) {
        xmin = std::min(xmin, c.x()), xmax = std::max(xmax, c.x()), ymin = std::min(ymin, c.y()), ymax = std::max(ymax, c.y());
        zmin = std::min(zmin, c.z());
      }
    // A ring of ground around the outline that the views do see: the exemplar fill continues
    // its texture, markings and kerbs (a parked car's own footprint is never seen).
    xmin -= o.context_m, ymin -= o.context_m, xmax += o.context_m, ymax += o.context_m;
    GroundMap gm;
    gm.res = std::max(o.bev_resolution_m, std::sqrt((xmax - xmin) * (ymax - ymin) / 2.0e6));  // at most ~2M cells
    gm.x0 = xmin, gm.y0 = ymin, gm.z = zmin;
    const int w = std::max(2, int(std::ceil((xmax - xmin) / gm.res))), h = std::max(2, int(std::ceil((ymax - ymin) / gm.res)));
    gm.radiance = cv::Mat(h, w, CV_32FC3, cv::Scalar::all(0));
    gm.seen = cv::Mat(h, w, CV_8U, cv::Scalar(0));
    gm.path = cv::Mat(h, w, CV_8U, cv::Scalar(0));
    for (const auto& tp : obj->track) {
      std::vector<cv::Point2f> cells;
      for (const auto& c : ground_outline(tp, obj->size_lwh, o)) cells.emplace_back(float((c.x() - xmin) / gm.res), float((c.y() - ymin) / gm.res));
      fill_convex_hull(gm.path, cells);
    }
    std::vector<std::vector<std::pair<float, cv::Vec3f>>> samples(size_t(w) * size_t(h));
    for (size_t i = 0; i < sources.size(); ++i) {
      const DeletionImage& im = sources[i];
      const Eigen::Isometry3d w2c = im.pose.inverse();
      for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u) {
          const Eigen::Vector3d p(gm.x0 + (u + 0.5) * gm.res, gm.y0 + (v + 0.5) * gm.res, gm.z);
          const Eigen::Vector3d c = w2c * p;
          if (c.z() < 0.5 || c.z() > 40) continue;
          const double px = im.cam.fx * c.x() / c.z() + im.cam.cx, py = im.cam.fy * c.y() / c.z() + im.cam.cy;
          if (px < 0 || py < 0 || px > im.cam.width - 1 || py > im.cam.height - 1) continue;
          if (occluded[i].at<uchar>(int(py + 0.5), int(px + 0.5))) continue;
          // Nearer views resolve the ground better: weight by inverse squared distance.
          samples[size_t(v) * size_t(w) + size_t(u)].emplace_back(float(1.0 / (c.squaredNorm())), bilinear(im.radiance, px, py));
        }
    }
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u) {
        auto& sm = samples[size_t(v) * size_t(w) + size_t(u)];
        if (sm.empty()) continue;
        // Robust: the weighted mean of the samples near the median brightness.
        std::vector<float> lum;
        for (const auto& [wt, c] : sm) lum.push_back(c[0] + c[1] + c[2]);
        std::nth_element(lum.begin(), lum.begin() + long(lum.size() / 2), lum.end());
        const float med = lum[lum.size() / 2];
        cv::Vec3f acc(0, 0, 0);
        float wsum = 0;
        for (const auto& [wt, c] : sm) {
          const float l = c[0] + c[1] + c[2];
          if (std::abs(l - med) > 0.25f * med + 1e-6f) continue;
          acc += c * wt;
          wsum += wt;
        }
        if (wsum <= 0) continue;
        gm.radiance.at<cv::Vec3f>(v, u) = acc / wsum;
        gm.seen.at<uchar>(v, u) = 255;
      }
    seen_cells += cv::countNonZero(gm.seen);
    all_cells += double(w) * h;
    // What nobody saw: exemplar fill in the bird's-eye view.
    const cv::Mat hole = gm.seen == 0;
    gm.valid = gm.seen.clone();
    if (cv::countNonZero(hole) > 0 && cv::countNonZero(gm.seen) > 0) {
      // Matching in sqrt space weighs dark asphalt and bright markings more evenly.
      cv::Mat root;
      cv::sqrt(gm.radiance, root);
      root = exemplar_inpaint(root, hole, {9, 60});
      gm.radiance = root.mul(root);
      gm.valid.setTo(255);
    }
    maps.push_back(gm);
  }
  stats.ground_seen = all_cells > 0 ? seen_cells / all_cells : 0;
  // Write back.
  const double min_depression = o.min_ground_depression_deg * M_PI / 180;
  for (auto& im : targets) {
    cv::Mat mask(im.cam.height, im.cam.width, CV_8U, cv::Scalar(0));
    cv::Mat owner(im.cam.height, im.cam.width, CV_32S, cv::Scalar(-1));
    for (size_t k = 0, m = 0; k < ids.size(); ++k) {
      const auto* obj = s.object(ids[k]);
      if (obj == nullptr || obj->track.empty()) continue;
      cv::Mat mk = deletion_mask(s, im, {ids[k]}, o);
      mk.setTo(0, nearer_objects_mask(s, im, *obj, ids, mk));
      owner.setTo(int(m), mk & (owner < 0));
      mask |= mk;
      ++m;
    }
    const cv::Mat outlines = mask.clone();
    if (!im.rendered_depth.empty()) add_path_pixels(im, maps, deletion_mask(s, im, others, tight_outline(o)), mask, owner);
    if (cv::countNonZero(mask) == 0) continue;
    ++stats.images_edited;
    cv::Mat filled = im.radiance.clone();
    cv::Mat fallback(mask.size(), CV_8U, cv::Scalar(0));
    const Eigen::Matrix3d R = im.pose.linear();
    const Eigen::Vector3d C = im.pose.translation();
    for (int y = 0; y < mask.rows; ++y)
      for (int x = 0; x < mask.cols; ++x) {
        if (!mask.at<uchar>(y, x)) continue;
        const int k = owner.at<int>(y, x);
        bool done = false;
        if (k >= 0 && size_t(k) < maps.size()) {
          const GroundMap& gm = maps[size_t(k)];
          const Eigen::Vector3d d = R * Eigen::Vector3d((x - im.cam.cx) / im.cam.fx, (y - im.cam.cy) / im.cam.fy, 1);
          if (d.z() < -1e-6) {
            const double t = (gm.z - C.z()) / d.z();
            const Eigen::Vector3d p = C + t * d;
            const double depression = std::atan2(C.z() - gm.z, (p - C).head<2>().norm());
            if (gm.contains(p.x(), p.y()) && depression >= min_depression) {
              filled.at<cv::Vec3f>(y, x) = bilinear(gm.radiance, (p.x() - gm.x0) / gm.res - 0.5, (p.y() - gm.y0) / gm.res - 0.5);
              done = true;
            }
          }
        }
        if (!done) fallback.at<uchar>(y, x) = 255;
      }
    if (const cv::Mat path = mask & ~outlines; o.path_min_log_step > 0 && cv::countNonZero(path) > 0)
      keep_unghosted_ground(im.radiance, path, o.path_min_log_step, filled, mask);
    stats.fallback_pixels += cv::countNonZero(fallback);
    if (cv::countNonZero(fallback) > 0) {
      const BackgroundView bg = background ? background(im, ids) : BackgroundView{};
      bool use_field = !bg.radiance.empty();
      if (use_field && !bg.depth.empty() && o.max_field_in_front_share < 1)
        use_field = share_in_front_of_boxes(s, im, ids, fallback, bg.depth, o.field_depth_check_max_m, 4) <= o.max_field_in_front_share;
      if (!bg.radiance.empty()) ++(use_field ? stats.field_fills : stats.field_rejected);
      if (use_field) {
        bg.radiance.copyTo(filled, fallback);
      } else {
        // 2D inpainting around the pixels no map covers, from everything not masked.
        cv::Rect roi = cv::boundingRect(fallback);
        roi = cv::Rect(roi.x - 24, roi.y - 24, roi.width + 48, roi.height + 48) & cv::Rect(0, 0, mask.cols, mask.rows);
        cv::Mat hole = fallback(roi).clone();
        // Known pixels: not masked at all, or already filled from a ground map.
        cv::Mat root;
        cv::sqrt(cv::max(filled(roi), 0.0), root);
        // Labelled objects that stay are no source: a bus beside a removed car must not
        // spread into what stood behind the car.
        const cv::Mat kept = deletion_mask(s, im, others, tight_outline(o))(roi).clone();
        // 80 px: sources from beside must reach past the sides of a car-wide hole.
        const cv::Mat out = exemplar_inpaint(root, hole, {7, 80, o.fill_beside_slope}, kept);
        cv::Mat sq = out.mul(out);
        sq.copyTo(filled(roi), hole);
      }
    }
    harmonize_fill(filled, im.radiance, mask);
    // Feathered seam: blend over a few pixels outside the mask.
    cv::Mat alpha;
    mask.convertTo(alpha, CV_32F, 1.0 / 255);
    if (o.feather_px > 0) {
      cv::Mat grown;
      cv::dilate(mask, grown, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * o.feather_px + 1, 2 * o.feather_px + 1)));
      cv::GaussianBlur(alpha, alpha, cv::Size(0, 0), o.feather_px / 2.0 + 0.5);
      alpha.setTo(1, mask);
      alpha.setTo(0, grown == 0);
    }
    for (int y = 0; y < mask.rows; ++y)
      for (int x = 0; x < mask.cols; ++x) {
        const float a = alpha.at<float>(y, x);
        if (a <= 0) continue;
        // Outside the mask the fill is the original itself, except where 2D inpainting
        // extended it: blend toward the filled value only where it exists.
        im.radiance.at<cv::Vec3f>(y, x) = im.radiance.at<cv::Vec3f>(y, x) * (1 - a) + filled.at<cv::Vec3f>(y, x) * a;
      }
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return stats;
}

BackgroundRenderer field_renderer(std::shared_ptr<const gs::RadianceField> model, const scene::Scene& s, const DeletionOptions& o,
                                  RenderKeeper keep) {
  return [model, &s, o, keep](const DeletionImage& im, const std::vector<std::string>& hidden) {
    cv::Rect roi = cv::boundingRect(deletion_mask(s, im, hidden, o));
    if (roi.empty()) return BackgroundView{cv::Mat(im.cam.height, im.cam.width, CV_32FC3, cv::Scalar::all(0)), cv::Mat()};
    roi = cv::Rect(roi.x - 2, roi.y - 2, roi.width + 4, roi.height + 4) & cv::Rect(0, 0, im.cam.width, im.cam.height);
    const gs::GsImage rendered = model->render_region(s, im.cam, im.pose, im.time, hidden, roi);
    if (keep) keep(im, rendered);
    return BackgroundView{cv::Mat(rendered.radiance * field_to_image_units(*model, s, im)), rendered.depth};
  };
}

}  // namespace chatsim::render::inpaint
