#include "agents/motion/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "agents/language/lane_names.hpp"
#include "agents/motion/planner_impl.hpp"

namespace chatsim::agents::motion {

using detail::dir_of;
using detail::kPi;

namespace {
constexpr size_t kMaxCandidates = 150;
constexpr size_t kMaxWaitingStarts = 4;  // the best starts that met traffic: each may wait for a gap
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
    Obstacle ob{o.id, o.size_lwh, {}, o.has_category_prefix("human")};
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

Obstacle ego_obstacle(const scene::Scene& scene) {
  constexpr double kLength = 4.6, kWidth = 1.9, kHeight = 1.6;
  const double ahead = scene.ego_origin == "rear_axle" ? 1.4 : 0.0;  // rear axle to box centre
  Obstacle ob{"ego", {kLength, kWidth, kHeight}, {}};
  for (const auto& f : scene.frames) {
    const Eigen::Vector3d p = f.ego_to_world.translation();
    const Eigen::Vector3d x = f.ego_to_world.linear().col(0);
    const double yaw = std::atan2(x.y(), x.x());
    ob.poses.emplace_back(Pose2{p.x() + ahead * std::cos(yaw), p.y() + ahead * std::sin(yaw), yaw});
  }
  return ob;
}

namespace detail {

// "park it in the parking lane": the side of the road the nearest parking lane is on (the right
// where there is none).
std::string nearest_parking_side(const scene::Scene& scene) {
  const auto nearest = scene.lanes.nearest(ego_frame(scene).p, "parking");
  if (!nearest) return "right_front";
  const Eigen::Vector2d pe = ego_frame(scene).to_ego(scene.lanes.point_at(nearest->lane, nearest->s));
  return pe.y() > 0 ? "left_front" : "right_front";
}

// How much the road the ego drives on climbs over the next 20 m of its way (metres; negative:
// it descends), from the heights of the lane map's centreline.
double ego_climb(const scene::Scene& scene) {
  const EgoFrame ego = ego_frame(scene);
  const auto at = scene.lanes.nearest(ego.p, "driving");
  if (!at) return 0;
  const auto& lane = scene.lanes.lanes()[size_t(at->lane)];
  const auto height = [&](double s) {
    s = std::clamp(s, 0.0, lane.length());
    const size_t i = std::min<size_t>(size_t(std::upper_bound(lane.s.begin(), lane.s.end(), s) - lane.s.begin()),
                                      lane.s.size() - 1);
    if (i == 0) return lane.centerline.front().z();
    const double t = (s - lane.s[i - 1]) / std::max(1e-9, lane.s[i] - lane.s[i - 1]);
    return lane.centerline[i - 1].z() + t * (lane.centerline[i].z() - lane.centerline[i - 1].z());
  };
  const double forward = std::cos(wrap(at->tangent_yaw - ego.yaw)) >= 0 ? 1 : -1;
  return height(at->s + forward * 20) - height(at->s);
}

Planner::Planner(const scene::Scene& scene, const PlanRequest& req) : scene_(scene), req_(req), m_(req.intent) {
  ego_ = ego_frame(scene);
  for (const auto& f : scene.frames) times_.push_back(f.timestamp_s - scene.frames.front().timestamp_s);
  if (times_.empty()) times_.push_back(0);
  // "keeping pace with me": the ego's mean speed along its recorded path (which may bend).
  for (size_t f = 1; f < scene.frames.size(); ++f) {
    const auto& a = scene.frames[f - 1].ego_to_world.translation();
    const auto& b = scene.frames[f].ego_to_world.translation();
    ego_speed_ += (b - a).head<2>().norm();
  }
  if (times_.back() > 0) ego_speed_ /= times_.back();
  if (req.ego_speed_mps) ego_speed_ = *req.ego_speed_mps;
  // "3 seconds ahead": at the speed of the vehicle it is measured from (the anchor, else the ego;
  // standing, the speed a car drives at, 8 m/s).
  if (m_.headway_s && !m_.distance_m) {
    const double from = m_.relative && req.anchor ? req.anchor->speed_mps : ego_speed_;
    m_.distance_m = *m_.headway_s * (from > 0.5 ? from : 8.0);
  }
  movable_ = req.type != "cone" && req.type != "barrier";
  if (!movable_) {
    m_.action = "static";
    m_.speed = "static";
  }
  if (!m_.relative && !m_.placement) m_.placement = m_.lane == "parking" ? nearest_parking_side(scene) : "front";
  // "on the right ... 70 m away": that far, a side is a side ahead, not level with the ego.
  if ((m_.placement == "left" || m_.placement == "right") && m_.distance_m && *m_.distance_m > 15)
    m_.placement = *m_.placement + "_front";
  // Overtaking from beside or ahead moves away from the ego's start; from behind it moves
  // toward it, which the lanes' own direction already gives.
  if (m_.overtake.value_or(false) && !m_.direction && m_.placement != "back") m_.direction = "away";
  // "coming down the hill": toward the ego where its road climbs, away where it descends.
  if (m_.slope && !m_.direction) {
    const double climb = ego_climb(scene);
    if (std::abs(climb) > 0.3) m_.direction = (climb > 0) == (m_.slope == "down") ? "toward" : "away";
  }
  // A side street on the left or right lies ahead of the ego on that side.
  if (m_.lane == "cross" && m_.placement == "left") m_.placement = "left_front";
  if (m_.lane == "cross" && m_.placement == "right") m_.placement = "right_front";
  // Per lane once, not per candidate start: whether the lane said ("the right lane") has a lane of
  // the ego's way beyond it on that side.
  // A turn pocket or an on-ramp beside the ego is not "the left lane": it is no through lane.
  if (m_.lane == "left" || m_.lane == "right")
    for (size_t li = 0; li < scene.lanes.lanes().size(); ++li) {
      lane_beside_.push_back(same_way_lane_beside(int(li), m_.lane == "left" ? 1 : -1));
      branch_.push_back(scene.lanes.diverges(int(li)) != 0 || scene.lanes.merges(int(li)));
    }
  // "in the bus lane": the map's lanes of that use; a map without one leaves the start free.
  if (m_.lane_use) use_lanes_ = language::lanes_for_use(scene, *m_.lane_use);
  // A bus lane is for buses (and a cycle lane for bicycles): others keep out unless told.
  for (const char* use : {"bus", "tram", "cycle"})
    if (!m_.lane_use && !(std::string(use) == "bus" && req.type == "bus"))
      for (int l : language::lanes_for_use(scene.lanes, use)) reserved_lanes_.push_back(l);
  if (m_.junction) junction_ = scene.lanes.junction_ahead(ego_.p, ego_.yaw);
  const auto ego_lane = scene.lanes.containing(ego_.p);
  for (const auto& l : ego_lane)
    if (scene.lanes.lanes()[size_t(l.lane)].type == "driving") {
      ego_lane_ = l.lane;
      ego_lane_s_ = l.s;
      ego_lane_dir_ = std::cos(wrap(l.tangent_yaw - ego_.yaw)) >= 0 ? 1 : -1;
      break;
    }
  // "parked on the far side": beyond the nearest lane of oncoming traffic, on its side.
  if (m_.lane == "oncoming") {
    double nearest = 12;
    for (size_t li = 0; li < scene.lanes.lanes().size(); ++li) {
      const auto pos = scene.lanes.project(int(li), ego_.p);
      const double lat = lateral_of(int(li));
      if (scene.lanes.lanes()[li].type == "driving" && !same_way_as_ego(int(li), pos.s) && std::abs(lat) < nearest)
        nearest = std::abs(lat), oncoming_side_ = lat > 0 ? 1 : -1;
    }
  }
}

PlanResult Planner::run() {
  PlanResult best = run_once();
  bool best_collided = collided_, best_missed = best.ok && lane_missed_;
  // Nothing free (or nothing at all, or not on the lane asked for) near the place asked for: look
  // twice as far around it; for a turn or lane change at a distance said, then further still (one
  // behind slower traffic fits in the clip only from ahead of it).
  const bool manoeuvre = m_.action && (m_.action->rfind("turn_", 0) == 0 || m_.action->rfind("lane_change", 0) == 0);
  for (double widen : {2.0, 3.5}) {
    if (m_.relative || (best.ok && !best_collided && !best_missed) || (widen > 2.0 && !(m_.distance_m && manoeuvre)))
      break;
    widen_ = widen;
    collided_ = false;
    PlanResult next = run_once();
    // Better than what there is: clean, and on the lane asked for when what there is is clean
    // (or always, for a scene of many vehicles: one off its lane spoils the scene).
    const bool best_clean = best.ok && !best_collided;
    if (next.ok && !collided_ && !((best_clean || req_.strict) && lane_missed_)) {
      next.notes.push_back("nothing was free " + (m_.distance_m ? fmt(*m_.distance_m) + " m away" : "in the " +
                           describe_placement() + " region") + ", so it starts a little further round (" +
                           fmt(next.resolved.distance_m.value_or(0)) + " m away)");
      return next;
    }
    if (!best.ok) {
      best = next;
      best_collided = collided_;
      best_missed = next.ok && lane_missed_;
    }
  }
  // A path that meets another vehicle is no answer: say so instead of keeping it.
  if (best.ok && (best_collided || (req_.strict && best_missed))) {
    PlanResult refused;
    refused.reason = best_collided ? best.notes.back()
                                   : "no start on the " + lane_said() +
                                         " lane is free of the traffic there (its recorded vehicles would run into it;"
                                         " remove them first to fill that lane)";
    return refused;
  }
  return best;
}

PlanResult Planner::run_once() {
  PlanResult result;
  result.t_s = times_;
  if (scene_.lanes.empty()) return plan_without_lanes();
  if (auto parked = parked_off_lane()) return *parked;
  std::vector<Candidate> cands = m_.relative ? relative_candidates() : region_candidates();
  if (cands.empty()) {
    const std::string& region = m_.relative ? m_.relative->region : "";
    const std::string where = region == "front"    ? "in front of "
                              : region == "back"   ? "behind "
                              : region == "beyond" ? "past "
                              : region == "at"     ? "in the place of "
                              : region == "opposite" ? "opposite "
                                                     : region + " of ";
    result.reason = m_.relative ? "no lane position " + where + m_.relative->to + " is free on the lane map"
                                : "no lane in the " + describe_placement() + " region matches the request";
    return result;
  }
  std::stable_sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  // Free starts win; one held up behind traffic or leaving the lane map competes by its score
  // plus a penalty for that; a colliding one only when nothing else is left.
  std::optional<std::pair<Candidate, Evaluated>> best_colliding, best_imperfect;
  // Placed by another vehicle, the place said stands (a note says when the recorded drive meets
  // it); placed by the ego's surroundings, a start the recorded drive would run into loses. Behind
  // the ego nearly every start is caught up with or catches up, and an abstract scene's vehicles
  // (strict) are many: said, not searched round (it costs time: 82 -> 125 ms, 250 -> 310 ms).
  const bool ego_matters = !m_.relative && m_.placement.value_or("front") != "back" && !req_.strict;
  const double ego_penalty = ego_matters ? kMeetsEgoPenalty : 0.0;
  const auto cost = [&](const std::pair<Candidate, Evaluated>& ce) {
    return ce.first.score + ce.second.slow_penalty + (ce.second.truncated ? kLeavesMapPenalty : 0.0) +
           (ce.second.meets_ego >= 0 ? ego_penalty : 0.0);
  };
  std::string invalid_reason;
  // The best-scored starts only: each costs a path, car following and a collision check over the
  // clip, and a request nothing satisfies would otherwise try every lane metre (seconds).
  const size_t limit = std::min<size_t>(cands.size(), kMaxCandidates);
  std::vector<Candidate> joins_met;  // pulling out, met traffic: may wait for a gap (wait_for_gap)
  for (size_t i = 0; i < limit; ++i) {
    // Sorted by score, and a start costs at least its score: none from here beats the best
    // imperfect one (the same answer the clean-start test below gives, without the evaluation).
    if (best_imperfect && cost(*best_imperfect) <= cands[i].score) break;
    // A start inside another vehicle meets it at once: no better than any colliding start found
    // already (and no answer at all when strict), so not worth a path, car following and a
    // collision check.
    if ((best_colliding || req_.strict) && starts_inside_another(cands[i])) {
      if (invalid_reason.empty()) invalid_reason = "every start that matches the request meets another vehicle";
      continue;
    }
    Evaluated e = evaluate(cands[i]);
    if (!e.valid) {
      if (invalid_reason.empty()) invalid_reason = e.invalid_reason;
      continue;
    }
    if (e.first_collision >= 0) {
      if (!best_colliding || e.first_collision > best_colliding->second.first_collision) best_colliding = {cands[i], e};
      if (m_.action == "join" && !cands[i].parked && joins_met.size() < kMaxWaitingStarts) joins_met.push_back(cands[i]);
      continue;
    }
    if (!e.truncated && e.slowed_to < 0 && (e.meets_ego < 0 || !ego_matters)) {
      if (best_imperfect && cost(*best_imperfect) <= cands[i].score) break;
      return finish(cands[i], e, result);
    }
    if (!best_imperfect || cost({cands[i], e}) < cost(*best_imperfect)) best_imperfect = {cands[i], e};
  }
  if (!best_imperfect && !joins_met.empty())
    if (const auto waiting = wait_for_gap(joins_met)) return finish(waiting->first, waiting->second, result);
  if (best_imperfect) {
    const Evaluated& e = best_imperfect->second;
    result = finish(best_imperfect->first, e, result);
    if (e.slowed_to >= 0)
      result.notes.push_back("traffic ahead on its lane holds it to " + fmt(e.slowed_to) +
                             " m/s on average (it follows, it does not drive through)");
    if (e.truncated)
      result.notes.push_back("it drives off the mapped lanes at t = " + fmt(times_[e.poses.size() - 1]) +
                             " s and leaves the scene there");
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

bool Planner::starts_inside_another(const Candidate& c) const {
  const Eigen::Vector2d p = scene_.lanes.point_at(c.lane, c.s);
  const Pose2 start{p.x(), p.y(), scene_.lanes.tangent_yaw_at(c.lane, c.s) + (c.dir > 0 ? 0 : kPi)};
  // Overlapping by more than 0.3 m: the lane point is the start only up to the path's smoothing.
  return std::any_of(req_.obstacles.begin(), req_.obstacles.end(), [&](const Obstacle& ob) {
    return !ob.pedestrian && !ob.poses.empty() && ob.poses[0] &&
           boxes_overlap(start, req_.size_lwh, *ob.poses[0], ob.size_lwh, 1.0, -0.3);
  });
}

std::string Planner::fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

PlanResult Planner::finish(const Candidate& c, const Evaluated& e, PlanResult result) const {
  result.ok = true;
  if (!e.crosses_pedestrian.empty())
    result.notes.push_back("the recorded path of " + e.crosses_pedestrian + " runs through it");
  if (e.waits_s > 0)
    result.notes.push_back("it waits " + fmt(e.waits_s) + " s for a gap in the traffic, then pulls out");
  if (e.meets_ego >= 0)
    result.notes.push_back("the recorded drive runs into it at t = " + fmt(times_[size_t(e.meets_ego)]) +
                           " s (the camera car keeps its recorded path; slow the view, or place it further)");
  result.t_s.resize(e.poses.size());
  result.trajectory = e.poses;
  result.lane = scene_.lanes.lanes()[size_t(c.lane)].id;
  // The lane asked for had no start that works: say which lane it got instead.
  const bool edge_missed = m_.lane_edge && lane_edge_penalties()[size_t(c.lane)] > 1.0;
  lane_missed_ = edge_missed || lane_hint_penalty(c.lane, c.s, c.dir) >= 60;
  if (lane_missed_)
    result.notes.push_back("no start in the " + (edge_missed ? *m_.lane_edge : lane_said()) +
                           " lane was free of other traffic; it drives in lane " + result.lane + " instead");
  // "20 m ahead of the van" where traffic leaves no room there: say how far it is instead.
  if (m_.relative && m_.distance_m && req_.anchor &&
      (m_.relative->region == "front" || m_.relative->region == "back" || m_.relative->region == "beyond")) {
    // As gaps_from_anchor reads it: centre to centre, never closer than anchor_base_gap.
    const double want = std::max(*m_.distance_m, anchor_base_gap());
    const double got = (Eigen::Vector2d(e.poses.front().x, e.poses.front().y) -
                        Eigen::Vector2d(req_.anchor->start.x, req_.anchor->start.y)).norm();
    if (got > want + distance_tolerance(want))
      result.notes.push_back("nothing was free " + fmt(*m_.distance_m) + " m from " + m_.relative->to + "; it starts " +
                             fmt(got) + " m from it");
  }
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

std::optional<PlanResult> Planner::parked_off_lane() const {
  if (!m_.relative || !req_.anchor) return std::nullopt;
  const std::string& region = m_.relative->region;
  if (region != "at" && region != "left" && region != "right") return std::nullopt;
  const Anchor& a = *req_.anchor;
  const bool parked = wants_parked(false) || (a.speed_mps < 0.5 && nothing_said_about_motion());
  if (!parked || !scene_.lanes.containing({a.start.x, a.start.y}, 0.5).empty()) return std::nullopt;
  const auto taken_by = [&](const Pose2& at) -> std::string {
    for (size_t f = 0; f < times_.size(); ++f)
      for (const auto& ob : req_.obstacles)
        if (f < ob.poses.size() && ob.poses[f] && !ob.pedestrian &&
            boxes_overlap(at, req_.size_lwh, *ob.poses[f], ob.size_lwh, 1.0, kClearanceM))
          return ob.id + " stands there at t = " + fmt(times_[f]) + " s";
    return "";
  };
  // In its place, or beside it ("a motorbike parked next to the bicycles" on a pavement the map
  // does not draw): the side said first, then the other, a little further out each time.
  std::vector<Pose2> places;
  if (region == "at") {
    places.push_back({a.start.x, a.start.y, a.start.yaw});
  } else {
    const double first = (a.size_lwh.y() + req_.size_lwh.y()) / 2 + 0.4;
    const Eigen::Vector2d left(-std::sin(a.start.yaw), std::cos(a.start.yaw));
    for (const double side : {region == "left" ? 1.0 : -1.0, region == "left" ? -1.0 : 1.0})
      for (double out = first; out < first + 3.0; out += 0.5) {
        const Eigen::Vector2d p = Eigen::Vector2d(a.start.x, a.start.y) + side * out * left;
        places.push_back({p.x(), p.y(), a.start.yaw});
      }
  }
  PlanResult result;
  result.t_s = times_;
  for (const auto& at : places) {
    result.reason = taken_by(at);
    if (result.reason.empty()) {
      result.trajectory.assign(times_.size(), at);
      break;
    }
  }
  if (!result.reason.empty()) result.reason = "its place is taken: " + result.reason;
  result.ok = result.reason.empty();
  if (!result.ok) result.trajectory.clear();
  result.speed_mps = 0;
  result.resolved = m_;
  result.resolved.action = "static";
  result.resolved.speed = "static";
  return result;
}

PlanResult Planner::plan_without_lanes() const {
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

}  // namespace detail

PlanResult plan_motion(const scene::Scene& scene, const PlanRequest& request) {
  return detail::Planner(scene, request).run();
}

}  // namespace chatsim::agents::motion
