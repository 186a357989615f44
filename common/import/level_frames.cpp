#include "common/import/level_frames.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace chatsim::import {
namespace {

struct Observation {
  size_t object;  // index among the static objects
  int frame;
  Eigen::Vector3d center;
  bool used = true;
};

// The correction's height at a world point.
double lift(const FrameLevel& l, const Eigen::Vector2d& ego, const Eigen::Vector2d& at) {
  return l.height + l.slope_x * (at.x() - ego.x()) + l.slope_y * (at.y() - ego.y());
}

}  // namespace

std::map<int, FrameLevel> fit_frame_levels(const scene::Scene& s, const LevelOptions& o) {
  std::vector<Observation> obs;
  size_t statics = 0;
  for (const auto& ob : s.objects) {
    if (int(ob.track.size()) < o.min_track_frames) continue;
    Eigen::Vector2d lo(1e30, 1e30), hi(-1e30, -1e30);
    for (const auto& p : ob.track) lo = lo.cwiseMin(p.center.head<2>()), hi = hi.cwiseMax(p.center.head<2>());
    if ((hi - lo).maxCoeff() >= o.max_static_travel_m) continue;
    for (const auto& p : ob.track) obs.push_back({statics, p.frame, p.center});
    ++statics;
  }
  std::map<int, Eigen::Vector2d> ego;
  for (const auto& f : s.frames) ego[f.index] = f.ego_to_world.translation().head<2>();
  std::map<int, FrameLevel> levels;
  for (const auto& f : s.frames) levels[f.index] = {};
  std::vector<double> height(statics, 0.0);
  // Alternating least squares: each object's true height given the corrections, then each
  // frame's plane given the heights; after half the rounds, boxes far off their object's height
  // (a mislabelled or slowly moving one) are left out.
  constexpr int kRounds = 30;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<double> sum(statics, 0.0);
    std::vector<int> n(statics, 0);
    for (const auto& b : obs) {
      if (!b.used) continue;
      sum[b.object] += b.center.z() + lift(levels[b.frame], ego[b.frame], b.center.head<2>());
      ++n[b.object];
    }
    for (size_t k = 0; k < statics; ++k)
      if (n[k] > 0) height[k] = sum[k] / n[k];
    if (round == kRounds / 2)
      for (auto& b : obs)
        b.used = std::abs(b.center.z() + lift(levels[b.frame], ego[b.frame], b.center.head<2>()) - height[b.object]) < o.outlier_m;
    std::map<int, std::pair<Eigen::Matrix3d, Eigen::Vector3d>> normal;  // A(0, 0): the frame's boxes
    for (const auto& b : obs) {
      if (!b.used) continue;
      const Eigen::Vector2d d = b.center.head<2>() - ego[b.frame];
      const Eigen::Vector3d x(1, d.x(), d.y());
      auto& [A, y] = normal.try_emplace(b.frame, Eigen::Matrix3d::Zero(), Eigen::Vector3d::Zero()).first->second;
      A += x * x.transpose();
      y += x * (height[b.object] - b.center.z());
    }
    for (auto& [frame, level] : levels) {
      const auto it = normal.find(frame);
      const int m = it == normal.end() ? 0 : int(std::lround(it->second.first(0, 0)));
      if (m < o.min_objects_per_frame) {
        level = {};
        continue;
      }
      auto [A, y] = it->second;
      // A little ridge on the slopes: objects along one line leave the tilt across it open.
      A(1, 1) += m * 1.0, A(2, 2) += m * 1.0;
      const Eigen::Vector3d p = A.ldlt().solve(y);
      level = {p[0], p[1], p[2], m};
    }
  }
  // Frames with too few static objects: interpolated between their nearest fitted neighbours.
  std::vector<int> fitted;
  for (const auto& [frame, level] : levels)
    if (level.objects > 0) fitted.push_back(frame);
  if (fitted.size() < 2) return {};
  for (auto& [frame, level] : levels) {
    if (level.objects > 0) continue;
    const auto after = std::upper_bound(fitted.begin(), fitted.end(), frame);
    const int b = after == fitted.end() ? fitted.back() : *after;
    const int a = after == fitted.begin() ? fitted.front() : *(after - 1);
    const double t = b == a ? 0.0 : double(frame - a) / double(b - a);
    const FrameLevel& la = levels[a];
    const FrameLevel& lb = levels[b];
    // Heights as the lift at this frame's ego, so a slope carried over stays the same plane.
    const double ha = lift(la, ego[a], ego[frame]), hb = lift(lb, ego[b], ego[frame]);
    level = {ha + t * (hb - ha), la.slope_x + t * (lb.slope_x - la.slope_x), la.slope_y + t * (lb.slope_y - la.slope_y), 0};
  }
  // The world stays the first frame's ego pose: the plane every correction shares (unobservable:
  // it lifts every object alike) is the first frame's.
  const int first = s.frames.front().index;
  const FrameLevel base = levels[first];
  const Eigen::Vector2d base_ego = ego[first];
  for (auto& [frame, level] : levels) {
    level.height -= lift(base, base_ego, ego[frame]);
    level.slope_x -= base.slope_x;
    level.slope_y -= base.slope_y;
  }
  return levels;
}

void apply_frame_levels(scene::Scene& s, const std::map<int, FrameLevel>& levels) {
  std::map<int, Eigen::Isometry3d> correction;
  for (auto& f : s.frames) {
    const auto it = levels.find(f.index);
    if (it == levels.end()) continue;
    const FrameLevel& l = it->second;
    // z += h + sx (x - ex) + sy (y - ey): a small rotation about the ego (rotation vector
    // (sy, -sx, 0): its cross product with an offset lifts it by sx dx + sy dy) and a lift.
    const Eigen::Vector3d e = f.ego_to_world.translation();
    const Eigen::Vector3d w(l.slope_y, -l.slope_x, 0);
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    if (w.norm() > 0) t.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
    t.translation() = e + Eigen::Vector3d(0, 0, l.height) - t.linear() * e;
    correction[f.index] = t;
    f.ego_to_world = t * f.ego_to_world;
    for (auto& [name, image] : f.images)
      if (image.camera_to_world) image.camera_to_world = t * *image.camera_to_world;
  }
  for (auto& ob : s.objects)
    for (auto& p : ob.track)
      if (const auto it = correction.find(p.frame); it != correction.end()) p.center = it->second * p.center;
}

}  // namespace chatsim::import
