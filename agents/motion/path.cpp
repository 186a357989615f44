#include "agents/motion/path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace chatsim::agents::motion {
namespace {

constexpr double kPi = std::numbers::pi;

double wrap(double a) { return std::remainder(a, 2 * kPi); }

Eigen::Vector2d dir_of(double yaw) { return {std::cos(yaw), std::sin(yaw)}; }

}  // namespace

void Path::push(const Eigen::Vector2d& p) {
  if (!points.empty() && (p - points.back()).norm() < 1e-6) return;
  s.push_back(points.empty() ? 0.0 : s.back() + (p - points.back()).norm());
  points.push_back(p);
}

Eigen::Vector2d Path::at(double q) const {
  if (points.size() < 2) return points.empty() ? Eigen::Vector2d::Zero() : points[0];
  if (q >= s.back()) {  // beyond the end: continue straight
    const Eigen::Vector2d d = (points.back() - points[points.size() - 2]).normalized();
    return points.back() + (q - s.back()) * d;
  }
  if (q <= 0) return points[0];
  const size_t i = size_t(std::upper_bound(s.begin(), s.end(), q) - s.begin()) - 1;
  const double t = (q - s[i]) / (s[i + 1] - s[i]);
  return points[i] + t * (points[i + 1] - points[i]);
}

double Path::yaw_at(double q) const {
  if (points.size() < 2) return 0;
  // Direction over a short window, so polyline corners do not make the yaw jump.
  const double h = 0.75;
  const double a = std::max(0.0, q - h), b = std::max(q + h, a + 0.1);
  const Eigen::Vector2d d = at(b) - at(a);
  return std::atan2(d.y(), d.x());
}

double Path::curvature_at(double q) const {
  const double h = 1.0;
  const double dyaw = wrap(yaw_at(q + h) - yaw_at(q - h));
  return std::abs(dyaw) / (2 * h);
}

Path lane_path(const scene::LaneMap& map, int lane, double s0, int dir, double length, double step) {
  Path path;
  const double end_s = dir > 0 ? map.lanes()[size_t(lane)].length() : 0.0;
  double q = s0;
  double travelled = 0;
  while (travelled <= length) {
    if ((dir > 0 && q > end_s) || (dir < 0 && q < end_s)) break;
    path.push(map.point_at(lane, q));
    q += dir * step;
    travelled += step;
  }
  if (travelled <= length) {  // the lane ended: go on straight
    const double yaw = map.tangent_yaw_at(lane, end_s) + (dir > 0 ? 0 : kPi);
    const Eigen::Vector2d last = map.point_at(lane, end_s);
    for (double extra = step; travelled <= length; extra += step, travelled += step) path.push(last + extra * dir_of(yaw));
  }
  return path;
}

void append_hermite(Path& path, const Eigen::Vector2d& to, double to_yaw, double step) {
  const Eigen::Vector2d from = path.points.back();
  const double from_yaw = path.yaw_at(path.length());
  const double chord = (to - from).norm();
  const Eigen::Vector2d m0 = chord * 1.2 * dir_of(from_yaw), m1 = chord * 1.2 * dir_of(to_yaw);
  const int n = std::max(4, int(std::ceil(chord * 1.6 / step)));
  for (int i = 1; i <= n; ++i) {
    const double t = double(i) / n, t2 = t * t, t3 = t2 * t;
    path.push((2 * t3 - 3 * t2 + 1) * from + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * to + (t3 - t2) * m1);
  }
}

using scene::kJunctionReachM;

namespace {

// A turn at a roundabout: the ring the lane runs into, followed its way round to the first exit
// leaving the way the turn goes (left +90 deg, right -90 deg from the way in), or to the nth exit
// (nth > 0, any way), then that exit.
std::optional<TurnPlan> roundabout_path(const scene::LaneMap& map, int lane, double s0, int dir, int sign,
                                        double length, int nth = 0) {
  const auto& in = map.lanes()[size_t(lane)];
  const double end_s = dir > 0 ? in.length() : 0.0, ahead = dir * (end_s - s0);
  const double in_yaw = map.tangent_yaw_at(lane, s0) + (dir > 0 ? 0 : kPi);
  const Eigen::Vector2d end = map.point_at(lane, end_s);
  for (size_t r = 0; r < map.lanes().size(); ++r) {
    const auto& ring = map.lanes()[r];
    if (!ring.closes_on_itself() || ahead < 1 || std::abs(map.project(int(r), end).lateral) > kJunctionReachM) continue;
    const double around = ring.length(), s_in = map.project(int(r), end).s;
    const int ring_dir = ring.direction == scene::TrafficDirection::Backward ? -1 : 1;
    std::vector<std::pair<double, int>> exits;  // arc along the ring to each, its lane
    for (size_t e = 0; e < map.lanes().size(); ++e) {
      const auto& out = map.lanes()[e];
      if (e == r || int(e) == lane || out.type != "driving" || out.closes_on_itself()) continue;
      const double start_s = out.direction == scene::TrafficDirection::Backward ? out.length() : 0.0;
      const auto on_ring = map.project(int(r), map.point_at(int(e), start_s));
      if (std::abs(on_ring.lateral) > kJunctionReachM) continue;
      if (nth == 0 && std::abs(wrap(map.travel_yaw_at(int(e), start_s) - in_yaw - sign * kPi / 2)) > kPi / 4) continue;
      const double arc = std::fmod(ring_dir * (on_ring.s - s_in) + 2 * around, around);
      if (arc > 6) exits.emplace_back(arc, int(e));
    }
    std::sort(exits.begin(), exits.end());
    const size_t pick = nth > 0 ? size_t(nth - 1) : 0;
    if (exits.size() <= pick) continue;
    const auto* exit = &exits[pick];
    TurnPlan plan;
    plan.path = lane_path(map, lane, s0, dir, ahead);
    const size_t before = plan.path.points.size() - 1;  // from the lane's end: the entry is unmapped
    const auto ring_at = [&](double q) { return std::fmod(s_in + ring_dir * q + 2 * around, around); };
    append_hermite(plan.path, map.point_at(int(r), ring_at(4)), map.travel_yaw_at(int(r), ring_at(4)), 0.5);
    for (double q = 5; q <= exit->first - 3; q += 1.0) plan.path.push(map.point_at(int(r), ring_at(q)));
    const auto& out = map.lanes()[size_t(exit->second)];
    const int out_dir = out.direction == scene::TrafficDirection::Backward ? -1 : 1;
    const double out_s = (out_dir > 0 ? 0.0 : out.length()) + out_dir * 3.0;
    append_hermite(plan.path, map.point_at(exit->second, out_s), map.travel_yaw_at(exit->second, out_s), 0.5);
    plan.connector.assign(plan.path.points.begin() + long(before), plan.path.points.end());
    const Path rest = lane_path(map, exit->second, out_s, out_dir, std::max(0.0, length - plan.path.length()));
    for (const auto& p : rest.points) plan.path.push(p);
    plan.target_lane = out.id;
    return plan;
  }
  return std::nullopt;
}

}  // namespace

std::optional<TurnPlan> roundabout_exit_path(const scene::LaneMap& map, int lane, double s0, int dir, int nth,
                                             double length) {
  return roundabout_path(map, lane, s0, dir, 0, length, nth);
}

namespace {

// The turn at crossing c with the given radius: along the lane to a radius short of the crossing,
// a curve onto the other lane a radius past it, then along that lane.
std::optional<TurnPlan> turn_at(const scene::LaneMap& map, int lane, double s0, int dir, const scene::LaneCrossing& c,
                                double ahead, double radius, bool street_ends_here, double length) {
  const auto& other = map.lanes()[size_t(c.other)];
  // Legal travel on the other lane runs along its polyline unless it is a backward lane.
  const int other_dir = other.direction == scene::TrafficDirection::Backward ? -1 : 1;
  const double exit_s = c.s_other + other_dir * radius;
  if (exit_s < 0 || exit_s > other.length()) return std::nullopt;
  TurnPlan plan;
  // Out of a street's mouth: the turn starts a radius short of the lane it joins, not of the
  // street's end, so that it stays on the lanes (a quarter circle, not a bulge across the kerb).
  const double gap = street_ends_here ? std::abs(map.project(c.other, map.point_at(lane, c.s_self)).lateral) : 0.0;
  plan.path = lane_path(map, lane, s0, dir, std::clamp(ahead + gap - radius, 0.0, ahead));
  const size_t before = plan.path.points.size();
  append_hermite(plan.path, map.point_at(c.other, exit_s), map.travel_yaw_at(c.other, c.s_other));
  plan.connector.assign(plan.path.points.begin() + long(before), plan.path.points.end());
  const Path rest = lane_path(map, c.other, exit_s, other_dir, std::max(0.0, length - plan.path.length()));
  for (const auto& p : rest.points) plan.path.push(p);
  plan.target_lane = other.id;
  return plan;
}

// Whether a turn's curve lies on some lane (half its width and a little more) where it cuts the
// corner most: its middle half, sampled at a quarter, the middle and three quarters (each start
// tried plans a turn, so this is on the planner's hot path).
bool connector_on_lanes(const scene::LaneMap& map, const std::vector<Eigen::Vector2d>& connector) {
  if (connector.empty()) return true;
  int hint = -1;
  for (const double f : {0.25, 0.5, 0.75})
    if (!map.on_some_lane(connector[size_t(f * double(connector.size() - 1))], 0.3, hint)) return false;
  return true;
}

}  // namespace

std::optional<TurnPlan> turn_path(const scene::LaneMap& map, int lane, double s0, int dir, int sign, double length) {
  if (auto round = roundabout_path(map, lane, s0, dir, sign, length)) return round;
  const double travel_yaw = map.tangent_yaw_at(lane, s0) + (dir > 0 ? 0 : kPi);
  // Crossing streets, then side streets that meet this lane (T junctions), nearest first.
  auto meets = map.crossings(lane);
  for (const auto& j : map.junctions(lane, kJunctionReachM)) meets.push_back(j);
  std::stable_sort(meets.begin(), meets.end(),
                   [&](const scene::LaneCrossing& a, const scene::LaneCrossing& b) { return dir * a.s_self < dir * b.s_self; });
  for (const auto& c : meets) {
    const double ahead = dir * (c.s_self - s0);
    // A smooth turn, or a tight one from near the end of a side street (its mouth: the lane it
    // turns into lies beyond the street's end).
    const bool street_ends_here = std::abs(c.s_self - (dir > 0 ? map.lanes()[size_t(lane)].length() : 0.0)) < 0.5;
    const auto& other = map.lanes()[size_t(c.other)];
    if (other.type != "driving") continue;
    const double other_yaw = map.travel_yaw_at(c.other, c.s_other);
    const double want = wrap(travel_yaw + sign * kPi / 2);
    if (std::abs(wrap(other_yaw - want)) > kPi / 6) continue;
    // The smooth radius first; where its corner would cut across ground no lane covers (a side
    // street drawn from the kerb, no parking lane at the corner), a tighter one.
    std::optional<TurnPlan> loose;
    for (const double r : {9.0, 7.0, 5.5}) {
      double radius = r;
      if (ahead < radius + 1 && street_ends_here) radius = 5.0;
      if (ahead < radius + 1 && !(street_ends_here && ahead >= 1.0)) continue;
      auto plan = turn_at(map, lane, s0, dir, c, ahead, radius, street_ends_here, length);
      if (!plan) continue;
      if (connector_on_lanes(map, plan->connector)) return plan;
      if (!loose) loose = std::move(plan);
    }
    if (loose) return loose;
  }
  return std::nullopt;
}

namespace {

// Whether a driving lane starts where this one ends (within 3 m, within 30 deg of its way).
bool lane_goes_on(const scene::LaneMap& map, int lane, int dir) {
  const auto& l = map.lanes()[size_t(lane)];
  const double end_s = dir > 0 ? l.length() : 0.0;
  const Eigen::Vector2d end = map.point_at(lane, end_s);
  const double yaw = map.tangent_yaw_at(lane, end_s) + (dir > 0 ? 0 : kPi);
  for (size_t i = 0; i < map.lanes().size(); ++i) {
    const auto& o = map.lanes()[i];
    if (int(i) == lane || o.type != "driving") continue;
    const auto pos = map.project(int(i), end);
    const bool at_start = o.direction == scene::TrafficDirection::Backward ? pos.s > o.length() - 3 : pos.s < 3;
    if ((at_start || o.direction == scene::TrafficDirection::Both) && std::abs(pos.lateral) < 3 &&
        pos.s < o.length() - 1 && std::abs(wrap(map.travel_yaw_at(int(i), pos.s) - yaw)) < kPi / 6)
      return true;
  }
  return false;
}

}  // namespace

std::optional<RoadEndTurn> turn_where_lane_ends(const scene::LaneMap& map, int lane, double s0, int dir, double reach,
                                                 double length) {
  const auto& l = map.lanes()[size_t(lane)];
  const double to_end = dir > 0 ? l.length() - s0 : s0;
  if (l.type != "driving" || l.closes_on_itself() || to_end > reach || lane_goes_on(map, lane, dir))
    return std::nullopt;
  const Eigen::Vector2d end = map.point_at(lane, dir > 0 ? l.length() : 0.0);
  // Most lanes end at the map's edge with no road across: say so before building any turn.
  const double end_yaw = map.tangent_yaw_at(lane, dir > 0 ? l.length() : 0.0);
  bool road_across = false;
  for (size_t i = 0; i < map.lanes().size() && !road_across; ++i) {
    if (int(i) == lane || map.lanes()[i].type != "driving") continue;
    const auto pos = map.project(int(i), end);
    road_across = pos.s > 0 && pos.s < map.lanes()[i].length() && std::abs(pos.lateral) < kJunctionReachM &&
                  std::abs(std::cos(wrap(pos.tangent_yaw - end_yaw))) < 0.5;
  }
  if (!road_across) return std::nullopt;
  std::optional<RoadEndTurn> best;
  double best_gap = 1e9;
  for (const int sign : {-1, 1}) {
    auto plan = turn_path(map, lane, s0, dir, sign, length);
    if (!plan) continue;
    const int target = map.find(plan->target_lane);
    const double gap = target < 0 ? 1e9 : std::abs(map.project(target, end).lateral);
    if (gap < best_gap) {
      best_gap = gap;
      best = RoadEndTurn{sign, std::move(*plan)};
    }
  }
  return best;
}

namespace {

struct LaneBeside {
  int lane = -1;
  double lateral = 0;  // signed, left of travel positive
};

// The nearest driving lane other than `lane` whose centre lies `lat_min`..`lat_max` m to the
// `sign` side of p0 (facing yaw0) and whose traffic runs within `max_angle` of yaw0.
std::optional<LaneBeside> nearest_lane_beside(const scene::LaneMap& map, int lane, const Eigen::Vector2d& p0, double yaw0,
                                              int sign, double lat_min, double lat_max, double max_angle) {
  const Eigen::Vector2d normal(-std::sin(yaw0), std::cos(yaw0));  // left of travel
  std::optional<LaneBeside> best;
  for (size_t i = 0; i < map.lanes().size(); ++i) {
    if (int(i) == lane || map.lanes()[i].type != "driving") continue;
    const auto pos = map.project(int(i), p0);
    const double lateral = (map.point_at(int(i), pos.s) - p0).dot(normal);
    if (sign * lateral < lat_min || sign * lateral > lat_max) continue;
    if (std::abs(wrap(map.travel_yaw_at(int(i), pos.s) - yaw0)) > max_angle) continue;
    if (!best || std::abs(lateral) < std::abs(best->lateral)) best = LaneBeside{int(i), lateral};
  }
  return best;
}

}  // namespace

bool may_have_lane_beside(const scene::LaneMap& map, int lane, double s0, int dir, int sign) {
  // lane_change_path's bounds widened by what its heading, taken over the path's first 0.75 m,
  // may differ from the tangent's.
  const double yaw0 = map.tangent_yaw_at(lane, s0) + (dir > 0 ? 0 : kPi);
  return nearest_lane_beside(map, lane, map.point_at(lane, s0), yaw0, sign, 1.0, 7.0, kPi / 3).has_value();
}

LaneChangePlan lane_change_path(const scene::LaneMap& map, int lane, double s0, int dir, int sign, double length,
                                double start_after_m, double change_length_m) {
  LaneChangePlan plan;
  const Path base = lane_path(map, lane, s0, dir, length);
  // The neighbouring lane in the same travel direction, one lane to that side; none: one lane width.
  double offset = sign * map.lanes()[size_t(lane)].width;
  if (const auto beside = nearest_lane_beside(map, lane, base.at(0), base.yaw_at(0), sign, 1.5, 6.0, kPi / 4)) {
    offset = beside->lateral;
    plan.target_lane = map.lanes()[size_t(beside->lane)].id;
  }
  for (size_t i = 0; i < base.points.size(); ++i) {
    const double u = std::clamp((base.s[i] - start_after_m) / change_length_m, 0.0, 1.0);
    const double blend = u * u * u * (10 - 15 * u + 6 * u * u);  // quintic smoothstep: zero end slopes
    const double yaw = base.yaw_at(base.s[i]);
    plan.path.push(base.points[i] + blend * offset * Eigen::Vector2d(-std::sin(yaw), std::cos(yaw)));
  }
  return plan;
}

namespace {

// Whether every corner of the polyline turns by less than about 0.006 deg (most lane paths).
bool is_straight(const Path& path) {
  for (size_t i = 2; i < path.points.size(); ++i) {
    const Eigen::Vector2d a = path.points[i - 1] - path.points[i - 2], b = path.points[i] - path.points[i - 1];
    if (std::abs(a.x() * b.y() - a.y() * b.x()) > 1e-4 * a.norm() * b.norm() || a.dot(b) <= 0) return false;
  }
  return true;
}

}  // namespace

double arc_where_turned(const Path& path, double from, double degrees) {
  const double yaw0 = path.yaw_at(from), limit = degrees * kPi / 180;
  const auto first = std::lower_bound(path.s.begin(), path.s.end(), from);
  for (auto it = first; it != path.s.end(); ++it)
    if (std::abs(wrap(path.yaw_at(*it) - yaw0)) >= limit) return *it;
  return std::numeric_limits<double>::infinity();
}

// The time a driver takes to steer through a change of heading (arc_lengths_at).
constexpr double kSpreadTurnS = 1.0;
constexpr double kTurnRad = 15.0 * std::numbers::pi / 180;

std::vector<double> arc_lengths_at(const Path& path, double v_desired, const std::vector<double>& times, double a_lat,
                                   double a_long, bool from_rest) {
  std::vector<double> out;
  out.reserve(times.size());
  if (v_desired <= 0 || path.points.size() < 2) {
    out.assign(times.size(), 0.0);
    return out;
  }
  // Speed limit per metre of path from curvature, then acceleration limits both ways.
  constexpr double ds = 0.5;  // half of curvature_at's 1 m: its headings fall on the grid
  const size_t n = size_t(std::ceil(path.length() / ds)) + 2;
  std::vector<double> v(n, v_desired);
  // A straight path (most lane paths) has no bend to slow for: skip sampling its curvature.
  if (!is_straight(path)) {
    // The heading change over windows of 2 to 32 m about each point. A driver spreads a slight
    // change of heading over about a second of travel: a window's curvature binds at the speeds
    // that cover it in a second or more, so a kink of a few degrees where two straight map
    // segments meet does not slow it as a bend does.
    // Turning summed without sign (an S-bend does not cancel out): turned[j] up to grid point j.
    constexpr int kPad = 32;  // grid steps of the longest half-window (16 m)
    std::vector<double> turned(n + 2 * kPad, 0.0);
    double last_yaw = path.yaw_at(-kPad * ds);
    for (size_t j = 1; j < turned.size(); ++j) {
      const double yaw = path.yaw_at((double(j) - kPad) * ds);
      turned[j] = turned[j - 1] + std::abs(wrap(yaw - last_yaw));
      last_yaw = yaw;
    }
    for (size_t i = 0; i < n; ++i) {
      double limit = 0;
      for (const int half : {2, 4, 8, 16, 32}) {  // grid steps: windows of 2, 4, 8, 16, 32 m
        const double window = 2 * half * ds;
        const double k = (turned[i + kPad + size_t(half)] - turned[i + kPad - size_t(half)]) / window;
        const double v_window = k > 1e-6 ? std::sqrt(a_lat / k) : v_desired;
        if (half == 2 || v_window >= window / kSpreadTurnS) limit = std::max(limit, v_window);
        if (limit >= v_desired) break;
        // A turn (15 degrees or more within 32 m) is driven by its tightest 2 m: only slight
        // bends and kinks are spread out.
        if (half == 2 && turned[i + 2 * kPad] - turned[i] >= kTurnRad) break;
      }
      v[i] = std::min(v_desired, limit);
    }
  }
  if (from_rest) v[0] = 0;
  for (size_t i = n - 1; i-- > 0;) v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * a_long * ds));
  for (size_t i = 1; i < n; ++i) v[i] = std::min(v[i], std::sqrt(v[i - 1] * v[i - 1] + 2 * a_long * ds));
  double s = 0, t = times.empty() ? 0 : times.front();
  const double dt = 0.005;
  for (const double target : times) {
    while (t + 1e-12 < target) {
      const size_t i = std::min(n - 1, size_t(s / ds));
      // From rest the first cell's speed is 0: its mean over the cell gets it moving.
      const double vi = from_rest ? 0.5 * (v[i] + v[std::min(n - 1, i + 1)]) : v[i];
      s += std::max(vi, 0.05) * dt;
      t += dt;
    }
    out.push_back(s);
  }
  return out;
}

std::vector<Pose2> bicycle_track(const Path& path, const std::vector<double>& arc, const std::vector<double>& times,
                                 double wheelbase, double max_steer, double max_steer_rate) {
  std::vector<Pose2> out;
  if (times.empty()) return out;
  const Eigen::Vector2d p0 = path.at(arc.front());
  double x = p0.x(), y = p0.y(), yaw = path.yaw_at(arc.front()), steer = 0;
  const double dt = 0.02;  // the shortest step, and the straight case's
  double t = times.front();
  size_t k = 0;
  auto reference = [&](double tt) {  // arc length of the reference at time tt
    if (tt <= times.front()) return arc.front();
    while (k + 1 < times.size() && times[k + 1] < tt) ++k;
    if (k + 1 >= times.size()) return arc.back();
    const double w = (tt - times[k]) / std::max(1e-9, times[k + 1] - times[k]);
    return arc[k] + w * (arc[k + 1] - arc[k]);
  };
  double bend_at = -1e9, max_lookahead = 1e9;
  out.push_back({x, y, wrap(yaw)});
  // Pure pursuit from on a straight path, heading along it, never steers: the vehicle moves
  // along the line by the reference's travel (what the steps below add up to, without them).
  if (is_straight(path)) {
    const Eigen::Vector2d along(std::cos(yaw), std::sin(yaw));
    for (size_t i = 1; i < times.size(); ++i) {
      while (t + 1e-9 < times[i]) t += dt;
      const Eigen::Vector2d p = p0 + (reference(t) - arc.front()) * along;
      out.push_back({p.x(), p.y(), wrap(yaw)});
    }
    return out;
  }
  double v = (reference(t + dt) - arc.front()) / dt;
  for (size_t i = 1; i < times.size(); ++i) {
    while (t + 1e-9 < times[i]) {
      // Steps of about 0.3 m of travel, 20 to 100 ms, ending on each frame: a slow vehicle (a
      // jam) needs few of them.
      const double h = std::min(std::clamp(0.3 / std::max(v, 1e-3), dt, 5 * dt), times[i] - t);
      const double s_now = reference(t), s_next = reference(t + h);
      v = (s_next - s_now) / h;
      // Pure pursuit cuts a bend of radius R by about L^2 / 2R: keep that within a metre. The
      // bend, half a look-ahead on, is looked up every 0.3 m (this runs for every step of every
      // candidate path).
      if (std::abs(s_now - bend_at) > 0.3) {
        const double k = path.curvature_at(s_now + 0.45 * std::max(3.0, v));
        max_lookahead = k > 1e-3 ? std::sqrt(2.0 / k) : 1e9;
        bend_at = s_now;
      }
      const double lookahead = std::max(2.5, std::min(std::max(3.0, 0.9 * v), max_lookahead));
      const Eigen::Vector2d to_target = path.at(s_now + lookahead) - Eigen::Vector2d(x, y);
      // sin of the angle from the heading to the target: the pure-pursuit law needs only that.
      const double c = std::cos(yaw), sn = std::sin(yaw);
      const double sin_alpha = (c * to_target.y() - sn * to_target.x()) / std::max(1e-9, to_target.norm());
      const double want = std::clamp(std::atan2(2 * wheelbase * sin_alpha, lookahead), -max_steer, max_steer);
      steer += std::clamp(want - steer, -max_steer_rate * h, max_steer_rate * h);
      x += v * c * h;
      y += v * sn * h;
      yaw += v / wheelbase * std::tan(steer) * h;
      t += h;
    }
    out.push_back({x, y, wrap(yaw)});
  }
  return out;
}

}  // namespace chatsim::agents::motion
