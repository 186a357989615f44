#include "agents/motion/planner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace chatsim::agents::motion {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

double wrap(double a) { return std::remainder(a, 2 * kPi); }
Eigen::Vector2d dir_of(double yaw) { return {std::cos(yaw), std::sin(yaw)}; }

// The ego at frame 0: the frame positions and regions are spoken in.
struct EgoFrame {
  Eigen::Vector2d p;
  double yaw = 0;
  Eigen::Vector2d to_ego(const Eigen::Vector2d& world) const {
    const Eigen::Vector2d d = world - p;
    return {std::cos(yaw) * d.x() + std::sin(yaw) * d.y(), -std::sin(yaw) * d.x() + std::cos(yaw) * d.y()};
  }
};

EgoFrame ego_frame(const scene::Scene& scene) {
  if (scene.frames.empty()) return {};
  const auto& t = scene.frames.front().ego_to_world;
  const Eigen::Vector3d x = t.linear().col(0);
  return {t.translation().head<2>(), std::atan2(x.y(), x.x())};
}

struct Region {
  double a_min = -180, a_max = 180;  // degrees, ego frame 0
  bool back = false;                 // |angle| >= a_min instead
  double d_min = 0, d_max = 1e9, d_pref = 15;
};

Region region_for(const std::string& placement, const MotionIntent& m, double widen = 1.0) {
  Region r;
  double d_default = 15;
  if (placement == "front") r = {-20, 20, false, 4, 70, 0};
  else if (placement == "left_front") r = {15, 70, false, 4, 45, 0}, d_default = 14;
  else if (placement == "right_front") r = {-70, -15, false, 4, 45, 0}, d_default = 14;
  else if (placement == "left") r = {65, 115, false, 1, 15, 0}, d_default = 3.5;
  else if (placement == "right") r = {-115, -65, false, 1, 15, 0}, d_default = 3.5;
  else if (placement == "back") r = {115, 180, true, 4, 70, 0};
  const bool side = placement == "left" || placement == "right";
  if (m.distance_word == "close") d_default = side ? 3.5 : 9;
  if (m.distance_word == "far") d_default = side ? 8 : 40;
  // "on the right, 20 m ahead": a side lane far ahead is only a few degrees off the axis.
  if (m.distance_m && placement == "left_front") r.a_min = 3;
  if (m.distance_m && placement == "right_front") r.a_max = -3;
  r.d_pref = m.distance_m.value_or(d_default);
  if (m.distance_m) {
    const double tol = std::max(3.0, 0.2 * *m.distance_m) * widen;
    r.d_min = std::max(0.5, *m.distance_m - tol);
    r.d_max = *m.distance_m + tol;
  }
  return r;
}

bool in_region(const Region& r, const Eigen::Vector2d& pe) {
  const double d = pe.norm();
  if (d < r.d_min || d > r.d_max) return false;
  const double a = std::atan2(pe.y(), pe.x()) / kDeg;
  return r.back ? std::abs(a) >= r.a_min : (a >= r.a_min && a <= r.a_max);
}

struct Candidate {
  int lane = -1;
  double s = 0;
  int dir = 1;            // travel along (+1) or against (-1) the polyline
  bool parked = false;    // evaluated as a parked vehicle
  double score = 0;
};

struct Evaluated {
  bool valid = false;
  std::string invalid_reason;
  std::vector<Pose2> poses;
  int first_collision = -1;  // frame index, -1: none
  std::string collides_with;
  std::string action;
  double speed = 0;
  bool truncated = false;    // leaves the lane map before the clip ends
};

int legal_dir(const scene::Lane& lane) { return lane.direction == scene::TrafficDirection::Backward ? -1 : 1; }

}  // namespace

double speed_for(const std::string& word) {
  if (word == "slow") return 4.0;
  if (word == "fast") return 14.0;
  if (word == "static") return 0.0;
  return 8.0;
}

bool boxes_overlap(const Pose2& a, const Eigen::Vector3d& sa, const Pose2& b, const Eigen::Vector3d& sb, double shrink,
                   double margin) {
  const Eigen::Vector2d ca(a.x, a.y), cb(b.x, b.y);
  const double ha[2] = {sa.x() / 2 * shrink + margin, sa.y() / 2 * shrink + margin};
  const double hb[2] = {sb.x() / 2 * shrink + margin, sb.y() / 2 * shrink + margin};
  if ((ca - cb).norm() > std::hypot(ha[0], ha[1]) + std::hypot(hb[0], hb[1])) return false;
  const Eigen::Vector2d axes[4] = {dir_of(a.yaw), dir_of(a.yaw + kPi / 2), dir_of(b.yaw), dir_of(b.yaw + kPi / 2)};
  const Eigen::Vector2d au = axes[0], av = axes[1], bu = axes[2], bv = axes[3];
  for (const auto& axis : axes) {
    const double ra = ha[0] * std::abs(au.dot(axis)) + ha[1] * std::abs(av.dot(axis));
    const double rb = hb[0] * std::abs(bu.dot(axis)) + hb[1] * std::abs(bv.dot(axis));
    if (std::abs((cb - ca).dot(axis)) > ra + rb) return false;
  }
  return true;
}

std::vector<Obstacle> scene_obstacles(const scene::Scene& scene, const std::vector<std::string>& removed) {
  std::vector<Obstacle> out;
  for (const auto& o : scene.objects) {
    if (std::find(removed.begin(), removed.end(), o.id) != removed.end()) continue;
    Obstacle ob{o.id, o.size_lwh, {}};
    for (size_t f = 0; f < scene.frames.size(); ++f) {
      const auto p = o.at(int(f));
      ob.poses.push_back(p ? std::optional<Pose2>(Pose2{p->center.x(), p->center.y(), p->yaw}) : std::nullopt);
    }
    out.push_back(std::move(ob));
  }
  return out;
}

Obstacle trajectory_obstacle(const std::string& id, const Eigen::Vector3d& size, const std::vector<Pose2>& trajectory) {
  Obstacle ob{id, size, {}};
  for (const auto& p : trajectory) ob.poses.emplace_back(p);
  return ob;
}

namespace {

class Planner {
 public:
  Planner(const scene::Scene& scene, const PlanRequest& req) : scene_(scene), req_(req), m_(req.intent) {
    ego_ = ego_frame(scene);
    for (const auto& f : scene.frames) times_.push_back(f.timestamp_s - scene.frames.front().timestamp_s);
    if (times_.empty()) times_.push_back(0);
    movable_ = req.type != "cone" && req.type != "barrier";
    if (!movable_) {
      m_.action = "static";
      m_.speed = "static";
    }
    if (!m_.relative && !m_.placement) m_.placement = m_.lane == "parking" ? "right_front" : "front";
    const auto ego_lane = scene.lanes.containing(ego_.p);
    for (const auto& l : ego_lane)
      if (scene.lanes.lanes()[size_t(l.lane)].type == "driving") {
        ego_lane_ = l.lane;
        break;
      }
  }

  PlanResult run() {
    PlanResult first = run_once();
    // Nothing free near the distance asked for: look twice as far either side before accepting a collision.
    if (first.ok && !first.notes.empty() && collided_ && m_.distance_m && !m_.relative) {
      widen_ = 2.0;
      collided_ = false;
      PlanResult second = run_once();
      if (second.ok && !collided_) return second;
    }
    return first;
  }

  PlanResult run_once() {
    PlanResult result;
    result.t_s = times_;
    if (scene_.lanes.empty()) return plan_without_lanes();
    std::vector<Candidate> cands = m_.relative ? relative_candidates() : region_candidates();
    if (cands.empty()) {
      result.reason = m_.relative ? "no lane position " + m_.relative->region + " of " + m_.relative->to +
                                        " is free on the lane map"
                                  : "no lane in the " + describe_placement() + " region matches the request";
      return result;
    }
    std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
    std::optional<std::pair<Candidate, Evaluated>> best_colliding, best_truncated;
    std::string invalid_reason;
    const size_t limit = std::min<size_t>(cands.size(), 400);
    for (size_t i = 0; i < limit; ++i) {
      Evaluated e = evaluate(cands[i]);
      if (!e.valid) {
        if (invalid_reason.empty()) invalid_reason = e.invalid_reason;
        continue;
      }
      if (e.first_collision < 0 && !e.truncated) return finish(cands[i], e, result);
      if (e.first_collision < 0) {
        if (!best_truncated) best_truncated = {cands[i], e};
        continue;
      }
      if (!best_colliding || e.first_collision > best_colliding->second.first_collision) best_colliding = {cands[i], e};
    }
    if (best_truncated) {
      result = finish(best_truncated->first, best_truncated->second, result);
      result.notes.push_back("it drives off the mapped lanes at t = " +
                             fmt(times_[best_truncated->second.poses.size() - 1]) + " s and leaves the scene there");
      return result;
    }
    if (best_colliding && req_.strict) {
      result.reason = "every start that matches the request meets another vehicle (first " +
                      best_colliding->second.collides_with + ")";
      return result;
    }
    if (best_colliding) {
      collided_ = true;
      result = finish(best_colliding->first, best_colliding->second, result);
      result.notes.push_back("no collision-free start matched the request; it meets " +
                             best_colliding->second.collides_with + " at t = " +
                             fmt(times_[size_t(best_colliding->second.first_collision)]) + " s");
      return result;
    }
    result.reason = invalid_reason.empty() ? "no start position fits the request" : invalid_reason;
    return result;
  }

 private:
  static std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", v);
    return buf;
  }

  std::string describe_placement() const { return m_.placement.value_or("front"); }

  bool nothing_said_about_motion() const {
    return !m_.action && !m_.speed && !m_.speed_mps && !m_.direction && !m_.wrong_way;
  }

  bool wants_parked(bool on_parking) const {
    if (!movable_) return true;
    if (m_.action == "static" || m_.speed == "static") return true;
    // A parking lane with no motion asked for: park there.
    return on_parking && !m_.action && !m_.speed && !m_.speed_mps && !m_.direction && !m_.wrong_way;
  }

  double lateral_of(int lane) const {  // signed ego-frame lateral offset of a lane near the ego
    const auto pos = scene_.lanes.project(lane, ego_.p);
    return ego_.to_ego(scene_.lanes.point_at(lane, pos.s)).y();
  }

  bool same_way_as_ego(int lane, double s) const {
    return std::cos(wrap(scene_.lanes.travel_yaw_at(lane, s) - ego_.yaw)) > 0;
  }

  double lane_hint_penalty(int lane, double s) const {
    if (!m_.lane) return 0;
    const auto& l = scene_.lanes.lanes()[size_t(lane)];
    const double lat = lateral_of(lane);
    if (*m_.lane == "ego") return lane == ego_lane_ ? 0 : 60;
    if (*m_.lane == "parking") return l.type == "parking" ? 0 : 60;
    if (*m_.lane == "oncoming") return l.type == "driving" && !same_way_as_ego(lane, s) ? std::abs(lat) * 0.5 : 60;
    if (*m_.lane == "left") return l.type == "driving" && lat > 1.5 && lat < 5.5 ? 0 : 60;
    if (*m_.lane == "right") return l.type == "driving" && lat < -1.5 && lat > -5.5 ? 0 : 60;
    return 0;
  }

  // Direction checks and preferences for one candidate travelling dir on lane.
  std::optional<double> direction_score(int lane, double s, int dir, bool parked) const {
    if (parked) return 0.0;
    const double heading = scene_.lanes.tangent_yaw_at(lane, s) + (dir > 0 ? 0 : kPi);
    const bool backward = m_.action == "backward";
    const double motion_yaw = heading + (backward ? kPi : 0);
    const Eigen::Vector2d p = scene_.lanes.point_at(lane, s);
    const bool toward = dir_of(motion_yaw).dot(ego_.p - p) > 0;
    if (m_.direction && (*m_.direction == "toward") != toward) return std::nullopt;
    double score = 0;
    if (!m_.direction && !m_.wrong_way && !m_.lane) {
      // Unsaid: traffic in the ego's direction is the usual picture.
      if (!same_way_as_ego(lane, s)) score += 8;
    }
    return score;
  }

  std::vector<Candidate> region_candidates() const {
    auto out = region_candidates(false);
    // Only a parking lane lies there: drive along it rather than refuse.
    if (out.empty()) out = region_candidates(true);
    return out;
  }

  std::vector<Candidate> region_candidates(bool moving_on_parking) const {
    std::vector<Candidate> out;
    const std::string placement = m_.placement.value_or("front");
    const Region region = region_for(placement, m_, widen_);
    const auto& lanes = scene_.lanes.lanes();
    for (size_t li = 0; li < lanes.size(); ++li) {
      const auto& lane = lanes[li];
      if (lane.type != "driving" && lane.type != "parking") continue;
      const bool parking = lane.type == "parking";
      const bool parked = wants_parked(parking);
      if (parking && !parked && !m_.lane && !moving_on_parking) continue;  // moving traffic stays off parking lanes
      std::vector<int> dirs;
      if (lane.direction == scene::TrafficDirection::Both) dirs = {1, -1};
      else dirs = {m_.wrong_way.value_or(false) ? -legal_dir(lane) : legal_dir(lane)};
      for (double s = 0.5; s < lane.length(); s += 1.0) {
        const Eigen::Vector2d pe = ego_.to_ego(scene_.lanes.point_at(int(li), s));
        if (!in_region(region, pe)) continue;
        for (int dir : dirs) {
          const auto ds = direction_score(int(li), s, dir, parked);
          if (!ds) continue;
          Candidate c{int(li), s, dir, parked, *ds};
          c.score += std::abs(pe.norm() - region.d_pref);
          c.score += lane_hint_penalty(int(li), s);
          if (placement == "front" || placement == "back") c.score += 1.5 * std::abs(pe.y());
          if (placement == "left" || placement == "right") c.score += 2.0 * std::abs(pe.y()) + 0.5 * std::abs(pe.x());
          if (parked && movable_ && !parking && (m_.action == "static")) c.score += 4;  // parked cars belong at the kerb
          if (!movable_ && parking) c.score += 3;
          out.push_back(c);
        }
      }
    }
    return out;
  }

  std::vector<Candidate> relative_candidates() const {
    std::vector<Candidate> out;
    if (!req_.anchor) return out;
    const Anchor& a = *req_.anchor;
    const Eigen::Vector2d ap(a.start.x, a.start.y);
    // The anchor's lane: the one it lies on whose direction matches its heading either way.
    int lane = -1;
    int dir = 1;
    double s0 = 0;
    double best = 1e9;
    for (const auto& pos : scene_.lanes.containing(ap, 0.5)) {
      const double d = std::abs(pos.lateral);
      if (d < best) {
        best = d;
        lane = pos.lane;
        s0 = pos.s;
        dir = std::cos(wrap(a.start.yaw - pos.tangent_yaw)) >= 0 ? 1 : -1;
      }
    }
    if (lane < 0) return out;
    const std::string region = m_.relative->region;
    const double base_gap = (a.size_lwh.x() + req_.size_lwh.x()) / 2 + 2.0;
    if (region == "front" || region == "back") {
      const int k = region == "front" ? 1 : -1;
      for (double gap = base_gap; gap < base_gap + 45; gap += 0.5) {
        const double s = s0 + k * dir * gap;
        if (s < 0 || s > scene_.lanes.lanes()[size_t(lane)].length()) continue;
        const bool parked = wants_parked(scene_.lanes.lanes()[size_t(lane)].type == "parking") ||
                            (a.speed_mps == 0 && nothing_said_about_motion());
        Candidate c{lane, s, dir, parked, gap - base_gap};
        out.push_back(c);
      }
    } else {
      const double side = region == "left" ? 1 : -1;
      const Eigen::Vector2d left(-std::sin(a.start.yaw), std::cos(a.start.yaw));
      for (size_t li = 0; li < scene_.lanes.lanes().size(); ++li) {
        if (int(li) == lane) continue;
        const auto pos = scene_.lanes.project(int(li), ap);
        const double lateral = (scene_.lanes.point_at(int(li), pos.s) - ap).dot(left);
        if (side * lateral < 1.5 || side * lateral > 8) continue;
        const auto& l = scene_.lanes.lanes()[li];
        const bool parked = wants_parked(l.type == "parking") || (a.speed_mps == 0 && nothing_said_about_motion());
        const int d2 = std::cos(wrap(a.start.yaw - pos.tangent_yaw)) >= 0 ? 1 : -1;
        for (double shift = 0; shift < 12; shift += 0.5)
          for (int sgn : {1, -1}) {
            const double s = pos.s + sgn * shift;
            if (s < 0 || s > l.length()) continue;
            out.push_back({int(li), s, d2, parked, std::abs(lateral) + shift});
          }
      }
    }
    // Explicit direction words override following the anchor's way.
    for (auto& c : out) {
      if (c.parked || !m_.direction) continue;
      const auto ds = direction_score(c.lane, c.s, c.dir, false);
      if (!ds) c.dir = -c.dir;
    }
    return out;
  }

  double desired_speed(bool parked) const {
    if (parked) return 0;
    if (m_.speed_mps) return *m_.speed_mps;
    const std::string word = m_.speed.value_or("normal");
    if (m_.chase.value_or(false) && req_.anchor && !m_.speed) return std::max(req_.anchor->speed_mps, 4.0);
    if (m_.action == "backward") return word == "fast" ? 5.0 : word == "slow" ? 2.0 : 3.0;
    return speed_for(word);
  }

  Evaluated evaluate(const Candidate& c) const {
    Evaluated e;
    e.speed = desired_speed(c.parked);
    const double total = e.speed * (times_.back() + 1) + 20;
    const auto& map = scene_.lanes;
    std::string action = c.parked ? "static" : m_.action.value_or("straight");
    Path path;
    bool reverse_yaw = false;
    if (action == "cut_in") {
      const double lat = ego_.to_ego(map.point_at(c.lane, c.s)).y();
      if (std::abs(lat) < 1.5) {
        e.invalid_reason = "cutting in needs a start in a lane beside the ego's";
        return e;
      }
      action = lat > 0 ? "lane_change_right" : "lane_change_left";
    }
    if (action == "static" || e.speed <= 0) {
      action = "static";
      e.speed = 0;
      path = lane_path(map, c.lane, c.s, c.dir, 1.0);
    } else if (action == "backward") {
      path = lane_path(map, c.lane, c.s, -c.dir, total);
      reverse_yaw = true;
    } else if (action == "turn_left" || action == "turn_right") {
      auto turn = turn_path(map, c.lane, c.s, c.dir, action == "turn_left" ? 1 : -1, total);
      if (!turn) {
        e.invalid_reason = std::string("no crossing lane ahead to turn ") + (action == "turn_left" ? "left" : "right") +
                           " into on the lane map";
        return e;
      }
      path = std::move(turn->path);
    } else if (action == "lane_change_left" || action == "lane_change_right") {
      const double start = std::max(4.0, e.speed * 1.0);
      const double length = std::max(15.0, e.speed * 3.0);
      auto lc = lane_change_path(map, c.lane, c.s, c.dir, action == "lane_change_left" ? 1 : -1, total, start, length);
      if (lc.target_lane.empty()) {
        e.invalid_reason = std::string("no lane to the ") + (action == "lane_change_left" ? "left" : "right") +
                           " in the same direction to change into";
        return e;
      }
      path = std::move(lc.path);
    } else {
      action = "straight";
      path = lane_path(map, c.lane, c.s, c.dir, total);
    }
    const auto arc = arc_lengths_at(path, e.speed, times_);
    if (action == "static" || reverse_yaw) {
      // Standing still, or reversing slowly along a straight lane: the path itself.
      for (double q : arc) {
        const Eigen::Vector2d p = path.at(q);
        e.poses.push_back({p.x(), p.y(), wrap(path.yaw_at(q) + (reverse_yaw ? kPi : 0))});
      }
    } else {
      e.poses = bicycle_track(path, arc, times_);
    }
    // The action must happen within the clip.
    const double turned = wrap(e.poses.back().yaw - e.poses.front().yaw) / kDeg;
    if (action == "turn_left" && turned < 60) return invalid(e, "the left turn does not fit in the clip from here");
    if (action == "turn_right" && turned > -60) return invalid(e, "the right turn does not fit in the clip from here");
    if (action.rfind("lane_change", 0) == 0) {
      const double yaw0 = e.poses.front().yaw;
      const Eigen::Vector2d d(e.poses.back().x - e.poses.front().x, e.poses.back().y - e.poses.front().y);
      const double lateral = -std::sin(yaw0) * d.x() + std::cos(yaw0) * d.y();
      if (std::abs(lateral) < 2.0) return invalid(e, "the lane change does not fit in the clip from here");
    }
    // A vehicle that drives off the mapped lanes leaves the scene: its trajectory ends there.
    size_t keep = e.poses.size();
    int lane_hint = c.lane;
    for (size_t f = 1; f < e.poses.size(); ++f)
      if (!scene_.lanes.on_some_lane({e.poses[f].x, e.poses[f].y}, 0.3, lane_hint)) {
        keep = f;
        break;
      }
    if (keep < 2) return invalid(e, "it would leave the mapped lanes at once");
    e.truncated = keep < e.poses.size();
    e.poses.resize(keep);
    e.valid = true;
    e.action = action;
    for (size_t f = 0; f < e.poses.size() && e.first_collision < 0; ++f)
      for (const auto& ob : req_.obstacles) {
        if (f >= ob.poses.size() || !ob.poses[f]) continue;
        if (boxes_overlap(e.poses[f], req_.size_lwh, *ob.poses[f], ob.size_lwh, 1.0, 0.25)) {
          e.first_collision = int(f);
          e.collides_with = ob.id;
          break;
        }
      }
    return e;
  }

  static Evaluated invalid(Evaluated e, const std::string& why) {
    e.valid = false;
    e.invalid_reason = why;
    return e;
  }

  PlanResult finish(const Candidate& c, const Evaluated& e, PlanResult result) const {
    result.ok = true;
    result.t_s.resize(e.poses.size());
    result.trajectory = e.poses;
    result.lane = scene_.lanes.lanes()[size_t(c.lane)].id;
    result.speed_mps = e.speed;
    result.resolved = m_;
    result.resolved.action = e.action;
    if (e.action == "static") result.resolved.speed = "static";
    else if (!m_.speed_mps) result.resolved.speed = e.speed < 6 ? "slow" : e.speed > 10 ? "fast" : "normal";
    const auto& start = e.poses.front();
    const Eigen::Vector2d pe = ego_.to_ego({start.x, start.y});
    if (!m_.relative) result.resolved.placement = m_.placement;
    result.resolved.distance_m = std::round(pe.norm() * 10) / 10;
    const bool legal = c.dir == legal_dir(scene_.lanes.lanes()[size_t(c.lane)]) ||
                       scene_.lanes.lanes()[size_t(c.lane)].direction == scene::TrafficDirection::Both;
    result.resolved.wrong_way = e.action != "static" && !legal;
    if (e.action != "static") {
      const Eigen::Vector2d p(start.x, start.y), q(e.poses[std::min<size_t>(e.poses.size() - 1, 10)].x,
                                                   e.poses[std::min<size_t>(e.poses.size() - 1, 10)].y);
      result.resolved.direction = (q - p).dot(ego_.p - p) > 0 ? "toward" : "away";
    }
    return result;
  }

  PlanResult plan_without_lanes() const {
    // No lane map: straight lines in the ego's heading, placed by region only.
    PlanResult result;
    result.t_s = times_;
    const std::string placement = m_.placement.value_or("front");
    const Region region = region_for(placement, m_);
    const double a = placement == "front" ? 0 : placement == "left_front" ? 30 : placement == "right_front" ? -30
                   : placement == "left" ? 90 : placement == "right" ? -90 : 180;
    double d = region.d_pref;
    if (placement == "left" || placement == "right") d = std::max(d, 3.5);
    Eigen::Vector2d pe = d * dir_of(a * kDeg);
    if (req_.anchor) {
      const auto& an = *req_.anchor;
      const double k = m_.relative && m_.relative->region == "back" ? -1 : 1;
      pe = ego_.to_ego(Eigen::Vector2d(an.start.x, an.start.y) + k * (an.size_lwh.x() + req_.size_lwh.x()) * dir_of(an.start.yaw));
    }
    const Eigen::Vector2d p = ego_.p + Eigen::Vector2d(std::cos(ego_.yaw) * pe.x() - std::sin(ego_.yaw) * pe.y(),
                                                       std::sin(ego_.yaw) * pe.x() + std::cos(ego_.yaw) * pe.y());
    const bool toward = m_.direction == "toward" || m_.wrong_way.value_or(false);
    const double yaw = ego_.yaw + (toward ? kPi : 0);
    const double v = desired_speed(m_.action == "static" || !movable_);
    const double sign = m_.action == "backward" ? -1 : 1;
    for (double t : times_) result.trajectory.push_back({p.x() + sign * v * t * std::cos(yaw), p.y() + sign * v * t * std::sin(yaw), wrap(yaw)});
    result.ok = true;
    result.speed_mps = v;
    result.resolved = m_;
    if (m_.action && *m_.action != "straight" && *m_.action != "static" && *m_.action != "backward")
      result.not_done.push_back("the scene has no lane map, so '" + *m_.action + "' was planned as driving straight");
    result.resolved.action = v == 0 ? "static" : (m_.action == "backward" ? "backward" : "straight");
    return result;
  }

  const scene::Scene& scene_;
  const PlanRequest& req_;
  MotionIntent m_;
  EgoFrame ego_;
  std::vector<double> times_;
  bool movable_ = true;
  int ego_lane_ = -1;
  double widen_ = 1.0;     // distance tolerance factor (see run)
  bool collided_ = false;  // the last run_once accepted a collision
};

}  // namespace

PlanResult plan_motion(const scene::Scene& scene, const PlanRequest& request) {
  return Planner(scene, request).run();
}

}  // namespace chatsim::agents::motion
