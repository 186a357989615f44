#include "agents/motion/car_following.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace chatsim::agents::motion {
namespace {

constexpr double kWindowM = 80.0;  // how far ahead along the path a leader is looked for

// Where a box stands along the path: arc length and sideways offset of its centre (the nearest
// path point within `window` metres ahead of `from`), or nullopt past the path's end.
std::optional<std::pair<double, double>> on_path(const Path& path, const Eigen::Vector2d& p, double from, double window) {
  const size_t lo = size_t(std::lower_bound(path.s.begin(), path.s.end(), from) - path.s.begin());
  size_t hi = size_t(std::upper_bound(path.s.begin(), path.s.end(), from + window) - path.s.begin());
  if (lo >= hi) return std::nullopt;
  // Every 8th point first, then the points around the nearest of those: this runs for every
  // obstacle, frame and candidate start.
  constexpr size_t kStride = 8;
  const auto d2_at = [&](size_t i) { return (path.points[i] - p).squaredNorm(); };
  size_t best = lo;
  for (size_t i = lo; i < hi; i += kStride)
    if (d2_at(i) < d2_at(best)) best = i;
  const size_t from_i = best > lo + kStride ? best - kStride : lo;
  hi = std::min(hi, best + kStride + 1);
  for (size_t i = from_i; i < hi; ++i)
    if (d2_at(i) < d2_at(best)) best = i;
  if (path.s[best] >= path.length() - 1e-6) return std::nullopt;
  return std::make_pair(path.s[best], std::sqrt(d2_at(best)));
}

struct Leader {
  double gap = std::numeric_limits<double>::infinity();  // bumper to bumper, m
  double speed = 0;                                       // along the path, m/s
};

// The path's bounding box grown by how far sideways a leader's centre may stand: a box outside
// it is never on the path, and most boxes are (the other lanes), so this cheap test comes first.
struct Bounds {
  Eigen::Vector2d lo, hi;
  bool contains(const Pose2& q, double margin) const {
    return q.x >= lo.x() - margin && q.x <= hi.x() + margin && q.y >= lo.y() - margin && q.y <= hi.y() + margin;
  }
};

Bounds bounds_of(const Path& path) {
  Bounds b{Eigen::Vector2d::Constant(1e300), Eigen::Vector2d::Constant(-1e300)};
  for (const auto& p : path.points) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

double side_margin(const Eigen::Vector3d& own, const FollowedBox& o) { return (own.y() + o.size_lwh.y()) / 2 + 0.3; }

// The boxes that stand within the path's bounds at some frame: the only possible leaders.
std::vector<FollowedBox> near_path(const Bounds& b, const Eigen::Vector3d& own, const std::vector<FollowedBox>& others) {
  std::vector<FollowedBox> out;
  for (const auto& o : others)
    if (std::any_of(o.poses->begin(), o.poses->end(),
                    [&](const std::optional<Pose2>& q) { return q && b.contains(*q, side_margin(own, o)); }))
      out.push_back(o);
  return out;
}

Leader nearest_leader(const Path& path, const Bounds& bounds, double s, const Eigen::Vector3d& own,
                      const std::vector<FollowedBox>& others, size_t frame, double frame_dt) {
  Leader best;
  const Eigen::Vector2d here = path.at(s);
  for (const auto& o : others) {
    if (frame >= o.poses->size() || !(*o.poses)[frame]) continue;
    const Pose2& q = *(*o.poses)[frame];
    if (!bounds.contains(q, side_margin(own, o))) continue;
    // Far from where the vehicle is now: not within the window ahead (a cheap test first; this
    // runs for every obstacle, frame and candidate start).
    if ((Eigen::Vector2d(q.x, q.y) - here).squaredNorm() > kWindowM * kWindowM * 1.1) continue;
    const auto at = on_path(path, {q.x, q.y}, s, kWindowM);
    if (!at || at->first <= s) continue;
    if (at->second > side_margin(own, o)) continue;  // beside the path, not on it
    const double gap = at->first - s - (own.x() + o.size_lwh.x()) / 2;
    if (gap >= best.gap) continue;
    double along = 0;  // its speed along our path there
    if (frame + 1 < o.poses->size() && (*o.poses)[frame + 1]) {
      const Pose2& n = *(*o.poses)[frame + 1];
      const double yaw = path.yaw_at(at->first);
      const Eigen::Vector2d vel((n.x - q.x) / frame_dt, (n.y - q.y) / frame_dt);
      along = vel.x() * std::cos(yaw) + vel.y() * std::sin(yaw);
      // Crossing our path (a pedestrian, cross traffic): not a leader; the collision check decides.
      if (vel.norm() > 0.5 && std::abs(along) < 0.7 * vel.norm()) continue;
    }
    best.gap = gap;
    best.speed = along;
  }
  return best;
}

}  // namespace

std::vector<double> follow_leaders(const Path& path, const std::vector<double>& free_arc, const std::vector<double>& times,
                                   const Eigen::Vector3d& own_size, const std::vector<FollowedBox>& others,
                                   const IdmParams& p) {
  if (times.size() < 2 || free_arc.size() != times.size() || path.points.empty()) return free_arc;
  const Bounds bounds = bounds_of(path);
  const std::vector<FollowedBox> near = near_path(bounds, own_size, others);
  std::vector<double> out{free_arc.front()};
  double s = free_arc.front();
  double v = std::max(0.0, (free_arc[1] - free_arc[0]) / std::max(1e-6, times[1] - times[0]));
  for (size_t f = 0; f + 1 < times.size(); ++f) {
    const double frame_dt = std::max(1e-6, times[f + 1] - times[f]);
    // Desired speed here: the free-flow profile's (it already slows for curves).
    const double v0 = std::max(0.1, (free_arc[f + 1] - free_arc[f]) / frame_dt);
    Leader lead = nearest_leader(path, bounds, s, own_size, near, f, frame_dt);
    // A leader pulling away faster than we want to drive never holds us up: IDM would brake
    // hard to open its safe gap, and the traffic behind us would run into us.
    if (lead.speed >= v0 && lead.gap > 0) lead = Leader{};
    const int steps = 5;
    const double dt = frame_dt / steps;
    const double s_frame = s;
    for (int k = 0; k < steps; ++k) {
      double interaction = 0;
      if (std::isfinite(lead.gap)) {
        // The gap at the frame, closed by our travel and opened by the leader's since.
        const double gap = std::max(0.1, lead.gap - (s - s_frame) + lead.speed * k * dt);
        const double desired_gap =
            p.min_gap + std::max(0.0, v * p.headway_s + v * (v - lead.speed) / (2 * std::sqrt(p.max_accel * p.comfort_brake)));
        interaction = (desired_gap / gap) * (desired_gap / gap);
      }
      const double r2 = (v / v0) * (v / v0);  // (v/v0)^4 without pow: this runs per substep
      const double a = p.max_accel * (1 - r2 * r2 - interaction);
      v = std::max(0.0, v + a * dt);
      s += v * dt;
    }
    out.push_back(std::min(s, path.length()));
  }
  return out;
}

}  // namespace chatsim::agents::motion
