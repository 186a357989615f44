#include "agents/motion/planner_impl.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "agents/language/lane_names.hpp"

namespace chatsim::agents::motion::detail {

EgoFrame ego_frame(const scene::Scene& scene) {
  if (scene.frames.empty()) return {};
  const auto& t = scene.frames.front().ego_to_world;
  const Eigen::Vector3d x = t.linear().col(0);
  return {t.translation().head<2>(), std::atan2(x.y(), x.x())};
}

Region region_for(const std::string& placement, const MotionIntent& m, double widen) {
  Region r;
  double d_default = 15;
  if (placement == "front" && m.lane == "cross") r = {-75, 75, false, 4, 70, 0};  // side streets lie off the axis
  else if (placement == "front") r = {-20, 20, false, 4, 70, 0};
  else if (placement == "left_front") r = {15, 70, false, 4, 45, 0}, d_default = 14;
  else if (placement == "right_front") r = {-70, -15, false, 4, 45, 0}, d_default = 14;
  else if (placement == "left") r = {65, 115, false, 1, 15, 0}, d_default = 3.5;
  else if (placement == "right") r = {-115, -65, false, 1, 15, 0}, d_default = 3.5;
  else if (placement == "back") r = {115, 180, true, 4, 70, 0};
  const bool side = placement == "left" || placement == "right";
  // Parked "on the right": anywhere along that kerb in sight, not only straight beside the ego.
  if (side && (m.action == "static" || m.speed == "static" || m.lane == "parking") && !m.distance_m) {
    r.a_min = placement == "left" ? 20 : -160;
    r.a_max = placement == "left" ? 160 : -20;
    r.d_max = 40;
  }
  if (m.distance_word == "close") d_default = side ? 3.5 : 9;
  if (m.distance_word == "far") d_default = side ? 8 : 40;
  if (m.distance_word == "end" && !side) {
    d_default = 80;
    r.d_min = 50;
    r.d_max = 130;
  }
  // "on the right, 20 m ahead": a side lane far ahead is only a few degrees off the axis; so is
  // a side street some way up the road.
  const bool far_side = m.distance_m || m.lane == "cross";
  if (far_side && placement == "left_front") r.a_min = 3;
  if (far_side && placement == "right_front") r.a_max = -3;
  if (m.lane == "cross") r.d_max = 120;
  if (widen > 1 && !r.back && !m.distance_m) {  // a second look round (a distance widens by itself)
    const double extra = 20 * (widen - 1);
    r.a_min = r.a_min >= 0 ? std::max(0.0, r.a_min - extra) : std::max(-180.0, r.a_min - extra);
    r.a_max = r.a_max <= 0 ? std::min(0.0, r.a_max + extra) : std::min(180.0, r.a_max + extra);
    r.d_max *= widen;  // and further: free bays, or a lane beyond where recorded traffic gets to
  }
  r.d_pref = m.distance_m.value_or(d_default);
  if (m.distance_m) {
    const double tol = distance_tolerance(*m.distance_m) * widen;
    r.d_min = std::max(0.5, *m.distance_m - tol);
    r.d_max = *m.distance_m + tol;
  }
  return r;
}

std::vector<std::pair<double, double>> camera_bearings(const scene::Scene& scene) {
  std::vector<std::pair<double, double>> out;
  for (const auto& cam : scene.cameras) {
    if (cam.fx <= 0 || cam.width <= 0) continue;
    const Eigen::Vector3d axis = cam.sensor_to_ego.linear().col(2);  // OpenCV: +z looks out
    const double yaw = std::atan2(axis.y(), axis.x()) / kDeg;
    const double half = std::atan(cam.width / (2.0 * cam.fx)) / kDeg;
    out.emplace_back(yaw - half, yaw + half);
  }
  return out;
}

double degrees_out_of_sight(const std::vector<std::pair<double, double>>& bearings, const Eigen::Vector2d& pe) {
  if (bearings.empty()) return 0;
  const double a = std::atan2(pe.y(), pe.x()) / kDeg;
  double best = 360;
  for (const auto& [lo, hi] : bearings)
    for (const double turn : {-360.0, 0.0, 360.0}) {  // ranges may straddle +-180
      const double b = a + turn;
      best = std::min(best, b < lo ? lo - b : b > hi ? b - hi : 0.0);
    }
  return best;
}

bool in_region(const Region& r, const Eigen::Vector2d& pe) {
  const double d = pe.norm();
  if (d < r.d_min || d > r.d_max) return false;
  const double a = std::atan2(pe.y(), pe.x()) / kDeg;
  return r.back ? std::abs(a) >= r.a_min : (a >= r.a_min && a <= r.a_max);
}

bool Planner::nothing_said_about_motion() const {
  return !m_.action && !m_.speed && !m_.speed_mps && !m_.direction && !m_.wrong_way && !m_.chase.value_or(false);
}

bool Planner::wants_parked(bool on_parking) const {
  if (!movable_) return true;
  if (m_.action == "static" || m_.speed == "static") return true;
  // A parking lane with no motion asked for: park there.
  return on_parking && nothing_said_about_motion();
}

bool Planner::same_way_as_ego(int lane, double s) const {
  return std::cos(wrap(scene_.lanes.travel_yaw_at(lane, s) - ego_.yaw)) > 0;
}

double Planner::lane_hint_penalty(int lane, double s, int dir) const {
  const bool off_use = !use_lanes_.empty() && std::find(use_lanes_.begin(), use_lanes_.end(), lane) == use_lanes_.end();
  const bool reserved = std::find(reserved_lanes_.begin(), reserved_lanes_.end(), lane) != reserved_lanes_.end();
  return (off_use ? 60 : 0) + (reserved ? 20 : 0) + said_lane_penalty(lane, s, dir);
}

std::string Planner::lane_said() const {
  // As the user says it: "bus", "booth 3" (the messages add " lane").
  if (m_.lane_use && !use_lanes_.empty()) return language::use_words(*m_.lane_use, false);
  return m_.lane.value_or(m_.lane_edge.value_or(""));
}

double Planner::said_lane_penalty(int lane, double s, int dir) const {
  if (!m_.lane) return 0;
  const auto& l = scene_.lanes.lanes()[size_t(lane)];
  const double lat = lateral_of(lane);
  if (*m_.lane == "ego") return lane == ego_lane_ ? 0 : 60;
  if (*m_.lane == "parking") return l.for_stopping() ? 0 : 60;
  if (*m_.lane == "ramp") return scene_.lanes.merges(lane) ? 0 : 60;
  if (*m_.lane == "oncoming") {
    // Parked "on the other side of the road": a kerb or bay beyond the oncoming traffic.
    if (wants_parked(false) && l.for_stopping()) return oncoming_side_ * lat > 1.5 ? std::abs(lat) * 0.5 : 60;
    return l.type == "driving" && !same_way_as_ego(lane, s) ? std::abs(lat) * 0.5 : 60;
  }
  // "the right lane" where the ego drives in the rightmost lane: that lane (and so for the left).
  if (*m_.lane == "left" || *m_.lane == "right") {
    const int side = *m_.lane == "left" ? 1 : -1;
    const bool beside = side * lat > 1.5 && side * lat < 5.5;
    // Not "in the right lane alongside me": level with the ego, its own lane is not meant.
    const bool level = m_.placement == "left" || m_.placement == "right";
    const bool outermost_own =
        !level && std::abs(lat) <= 1.5 && same_way_as_ego(lane, s) && !lane_beside_[size_t(lane)];
    return l.type == "driving" && (beside || outermost_own) && !branch_[size_t(lane)] ? 0 : 60;
  }
  if (*m_.lane == "cross") {  // a lane across the ego's: a side or cross street
    if (l.type != "driving" || std::abs(std::cos(wrap(scene_.lanes.travel_yaw_at(lane, s) - ego_.yaw))) >= 0.5) return 60;
    // Turning out of a side street: its lane toward the road, not the one leading away from it.
    const bool turns_out = m_.action == "turn_left" || m_.action == "turn_right" || m_.action == "join";
    // Whether its way leads toward the ego's road or away from it, a few metres on (a two-way
    // driveway is driven either way; a cross street runs on across the road).
    const double here = std::abs(ego_.to_ego(scene_.lanes.point_at(lane, s)).y());
    const double on = s + 5.0 * ((dir != 0 ? dir : legal_dir(l)) > 0 ? 1 : -1);
    const bool leads_away = std::abs(ego_.to_ego(scene_.lanes.point_at(lane, on)).y()) > here;
    // Reversing out of it: facing up the street, on the lane leading away from the road.
    const bool reverses_out = m_.action == "backward";
    return (turns_out && leads_away) || (reverses_out && !leads_away) ? 60 : 0;
  }
  return 0;
}

// Direction checks and preferences for one candidate travelling dir on lane.
std::optional<double> Planner::direction_score(int lane, double s, int dir, bool parked) const {
  if (parked) return 0.0;
  const double heading = scene_.lanes.tangent_yaw_at(lane, s) + (dir > 0 ? 0 : kPi);
  const bool backward = m_.action == "backward";
  const double motion_yaw = heading + (backward ? kPi : 0);
  const Eigen::Vector2d p = scene_.lanes.point_at(lane, s);
  const bool toward = dir_of(motion_yaw).dot(ego_.p - p) > 0;
  // "turning out of the side street, heading away from us": a turn's direction is where it goes
  // after the turn, not how it starts.
  const bool turns = m_.action == "turn_left" || m_.action == "turn_right" || m_.action == "join";
  if (m_.direction && !turns && (*m_.direction == "toward") != toward) return std::nullopt;
  double score = 0;
  if (!m_.direction && !m_.wrong_way && !m_.lane) {
    // Unsaid: traffic in the ego's direction is the usual picture.
    if (!same_way_as_ego(lane, s)) score += 8;
  }
  return score;
}

std::vector<Candidate> Planner::region_candidates() const {
  auto out = region_candidates(false);
  // Only a parking lane lies there: drive along it rather than refuse.
  if (out.empty()) out = region_candidates(true);
  return out;
}

// "the lane next to the median" (inner), "the slow lane" (outer): among the driving lanes that run
// beside the ego the same way as a lane, the one nearest to (or farthest from) the lanes running
// the other way. Zero for every lane when nothing was said or no lane runs the other way.
std::vector<double> Planner::lane_edge_penalties() const {
  const auto& lanes = scene_.lanes.lanes();
  if (!m_.lane_edge) return std::vector<double>(lanes.size(), 0.0);
  // As strong as a named lane: a lane that is none of the road's through lanes is not it.
  std::vector<double> out(lanes.size(), 60.0);
  struct Beside {
    size_t lane;
    double lateral;
    bool same_way;
  };
  std::vector<Beside> beside;
  for (size_t li = 0; li < lanes.size(); ++li) {
    if (lanes[li].type != "driving" || lanes[li].direction == scene::TrafficDirection::Both) continue;
    const double s = scene_.lanes.project(int(li), ego_.p).s;
    const Eigen::Vector2d pe = ego_.to_ego(scene_.lanes.point_at(int(li), s));
    if (std::abs(pe.x()) > 15 || std::abs(std::cos(wrap(scene_.lanes.travel_yaw_at(int(li), s) - ego_.yaw))) < 0.7)
      continue;  // a side street, or a lane that ends before reaching the ego
    beside.push_back({li, pe.y(), same_way_as_ego(int(li), s)});
  }
  std::vector<double> gap(lanes.size(), -1.0);  // lateral distance to the nearest lane the other way
  for (const auto& b : beside)
    for (const auto& o : beside)
      if (o.same_way != b.same_way)
        gap[b.lane] = gap[b.lane] < 0 ? std::abs(b.lateral - o.lateral) : std::min(gap[b.lane], std::abs(b.lateral - o.lateral));
  // "the slow lane" is of the ego's way unless the other way is said.
  const bool other_way = m_.lane == "oncoming" || m_.direction == "toward";
  for (const auto& b : beside) {
    out[b.lane] = b.same_way == other_way ? 60 : 0;
    if (gap[b.lane] < 0 || out[b.lane] > 0) continue;
    double lo = gap[b.lane], hi = gap[b.lane];
    for (const auto& o : beside)
      if (o.same_way == b.same_way && gap[o.lane] >= 0) {
        lo = std::min(lo, gap[o.lane]);
        hi = std::max(hi, gap[o.lane]);
      }
    out[b.lane] = 15.0 * (*m_.lane_edge == "inner" ? gap[b.lane] - lo : hi - gap[b.lane]);
  }
  return out;
}

// "past the junction", "20 m before the crossing": distances counted from the first junction ahead,
// clear of the lanes crossing there.
void Planner::place_by_junction(const std::string& placement, double widen, Region& region) const {
  const bool after = *m_.junction == "after";
  const double edge = after ? junction_->to + 5 : junction_->from - 5;
  const double d = m_.distance_m.value_or(8.0);
  const double tol = m_.distance_m ? distance_tolerance(d) * widen : 1e9;
  region.d_pref = after ? edge + d : std::max(1.0, edge - d);
  region.d_min = after ? std::max(edge, region.d_pref - tol) : std::max(0.5, region.d_pref - tol);
  region.d_max = after ? region.d_pref + std::min(tol, 60.0 * widen) : std::min(edge, region.d_pref + tol);
  // Some way up the road, a side lane is only a few degrees off the axis.
  if (placement == "left_front") region.a_min = std::min(region.a_min, 3.0);
  if (placement == "right_front") region.a_max = std::max(region.a_max, -3.0);
}

Region Planner::search_region(const std::string& placement, double widen) const {
  Region region = region_for(placement, m_, widen);
  if (m_.junction && junction_) place_by_junction(placement, widen, region);
  // "on the farm track", "in the bus lane", "out of the driveway" with no side or distance:
  // wherever that lane is ahead.
  if ((!use_lanes_.empty() || m_.lane == "cross") && placement == "front" && !m_.distance_m) {
    region.a_min = std::min(region.a_min, -75.0);
    region.a_max = std::max(region.a_max, 75.0);
    region.d_max = std::max(region.d_max, 120.0);
  }
  return region;
}

std::optional<RoadPlace> Planner::bend_place(const Eigen::Vector2d& world, const Region& region,
                                             const std::string& placement) const {
  if (ego_lane_ < 0 || (placement != "front" && placement != "back")) return std::nullopt;
  // Along the road is never shorter than straight across: a point too far even straight across
  // (plus the road's width and the ego's offset in its lane) is out, without projecting it.
  if ((world - ego_.p).norm() > region.d_max + 10.0) return std::nullopt;  // runs for every lane metre
  const auto& map = scene_.lanes;
  const auto pos = map.project(ego_lane_, world);
  if (std::abs(pos.lateral) > 8.0) return std::nullopt;  // the ego's road: its lane and two beside
  const double along = (pos.s - ego_lane_s_) * ego_lane_dir_ * (placement == "front" ? 1 : -1);
  if (along < region.d_min || along > region.d_max) return std::nullopt;
  // On a straight road the angle window says it all; only a bend takes the road off the axis.
  const double lane_yaw = map.tangent_yaw_at(ego_lane_, pos.s) + (ego_lane_dir_ > 0 ? 0 : kPi);
  if (std::abs(wrap(lane_yaw - ego_.yaw)) < 15 * kDeg) return std::nullopt;
  return RoadPlace{along, pos.lateral};
}

bool Planner::stopping_lane_in(const Region& region) const {
  const auto& lanes = scene_.lanes.lanes();
  for (size_t li = 0; li < lanes.size(); ++li) {
    if (!lanes[li].for_stopping()) continue;
    for (double s = 0.5; s < lanes[li].length(); s += 1.0)
      if (in_region(region, ego_.to_ego(scene_.lanes.point_at(int(li), s)))) return true;
  }
  return false;
}

std::vector<Candidate> Planner::region_candidates(bool moving_on_parking) const {
  std::vector<Candidate> out;
  const auto edge_penalty = lane_edge_penalties();
  const std::string placement = m_.placement.value_or("front");
  const Region region = search_region(placement, widen_);
  // A second look round starts only where the first did not look: every start there was tried.
  const std::optional<Region> looked = widen_ > 1 ? std::optional(search_region(placement, 1.0)) : std::nullopt;
  // A lane said with no distance ("on the farm track"): wherever it is, rather than the usual
  // distance on another lane; nearer still better.
  const bool lane_without_distance = (m_.lane || m_.lane_edge || !use_lanes_.empty()) && !m_.distance_m;
  const auto& lanes = scene_.lanes.lanes();
  // "parked in the car park": in its bays, not in its aisle.
  const bool use_has_stopping =
      std::any_of(use_lanes_.begin(), use_lanes_.end(), [&](int l) { return lanes[size_t(l)].for_stopping(); });
  // Parked "on the left": at a parking lane on that side where the map has one in reach, not in
  // a lane of traffic; and where a camera sees it, not straight beside the ego.
  const bool side = placement == "left" || placement == "right";
  const bool parked_side = side && wants_parked(false);
  const bool kerb_in_reach = parked_side && stopping_lane_in(region);
  const std::vector<std::pair<double, double>> bearings =
      parked_side && m_.distance_word != "close" ? camera_bearings(scene_) : std::vector<std::pair<double, double>>{};
  for (size_t li = 0; li < lanes.size(); ++li) {
    const auto& lane = lanes[li];
    if (lane.type != "driving" && !lane.for_stopping()) continue;
    const bool parking = lane.for_stopping();
    const bool parked = wants_parked(parking);
    if (parking && !parked && !m_.lane && !moving_on_parking) continue;  // moving traffic stays off parking lanes
    if (movable_ && parked && !parking && (use_has_stopping || kerb_in_reach)) continue;
    std::vector<int> dirs;
    if (lane.direction == scene::TrafficDirection::Both) dirs = {1, -1};
    else dirs = {m_.wrong_way.value_or(false) ? -legal_dir(lane) : legal_dir(lane)};
    for (double s = 0.5; s < lane.length(); s += 1.0) {
      const Eigen::Vector2d world = scene_.lanes.point_at(int(li), s), pe = ego_.to_ego(world);
      const bool in_window = in_region(region, pe);
      const auto road = in_window ? std::nullopt : bend_place(world, region, placement);
      const bool looked_there = looked && (in_region(*looked, pe) || bend_place(world, *looked, placement));
      if ((!in_window && !road) || looked_there) continue;
      for (int dir : dirs) {
        const auto ds = direction_score(int(li), s, dir, parked);
        if (!ds) continue;
        Candidate c{int(li), s, dir, parked, *ds};
        const double off = std::abs((road ? road->along : pe.norm()) - region.d_pref);
        c.score += lane_without_distance ? std::min(off, 30.0) + 0.1 * off : off;
        c.score += lane_hint_penalty(int(li), s, dir) + edge_penalty[li];
        // Off to one side costs less where a lane was named: the lane says where ("in the car
        // park" beside the road).
        const double off_axis = !use_lanes_.empty() && !m_.distance_m ? 0.2 : 1.5;
        if (placement == "front" || placement == "back") c.score += off_axis * std::abs(road ? road->lateral : pe.y());
        // "Ahead" in a lane off to one side, no distance said: far enough up it to be in front.
        if (placement == "front" && !road && !m_.distance_m)
          c.score += 1.5 * std::max(0.0, std::abs(std::atan2(pe.y(), pe.x())) * 180 / std::numbers::pi - 20);
        if (side) c.score += 2.0 * std::abs(pe.y()) + 0.5 * std::abs(pe.x()) + 1.5 * degrees_out_of_sight(bearings, pe);
        if (parked && movable_ && !parking && (m_.action == "static")) c.score += 8;  // parked cars belong at the kerb
        if (!movable_ && parking) c.score += 3;
        // Coming down a side street: some way up it, so that it is seen coming, not born at the mouth.
        if (!parked && m_.lane == "cross") c.score += 0.5 * std::abs(std::abs(pe.y()) - 15.0);
        out.push_back(c);
      }
    }
  }
  return out;
}

std::vector<Candidate> Planner::relative_candidates() const {
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
  // Off every lane (a car park's bay, a kerb the map does not draw): the nearest lane beside it.
  if (lane < 0)
    for (size_t li = 0; li < scene_.lanes.lanes().size(); ++li) {
      if (scene_.lanes.lanes()[li].type != "driving" && !scene_.lanes.lanes()[li].for_stopping()) continue;
      const auto pos = scene_.lanes.project(int(li), ap);
      if (std::abs(pos.lateral) >= std::min(best, kOffLaneReachM)) continue;
      best = std::abs(pos.lateral);
      lane = int(li);
      s0 = pos.s;
      dir = std::cos(wrap(a.start.yaw - pos.tangent_yaw)) >= 0 ? 1 : -1;
    }
  const std::string region = m_.relative->region;
  if (region == "opposite") {
    opposite_candidates(out);
    return out;
  }
  if (lane < 0) return out;
  const double base_gap = anchor_base_gap();
  if (region == "at") {  // in its place: the anchor's own stretch of lane
    const bool parked = wants_parked(scene_.lanes.lanes()[size_t(lane)].for_stopping()) ||
                        (a.speed_mps < 0.5 && nothing_said_about_motion());
    for (double shift = 0; shift <= 10; shift += 0.5)
      for (int sgn : {1, -1}) {
        const double s = s0 + sgn * shift;
        if (s >= 0 && s <= scene_.lanes.lanes()[size_t(lane)].length()) out.push_back({lane, s, dir, parked, shift});
        if (shift == 0) break;
      }
    // Parked where a moving vehicle was: the kerb beside that place (traffic keeps using the lane).
    if (parked && !scene_.lanes.lanes()[size_t(lane)].for_stopping())
      for (size_t li = 0; li < scene_.lanes.lanes().size(); ++li) {
        const auto& l = scene_.lanes.lanes()[li];
        const auto pos = scene_.lanes.project(int(li), ap);
        if (!l.for_stopping() || std::abs(pos.lateral) > 5) continue;
        for (double shift = 0; shift <= 10; shift += 0.5)
          for (int sgn : {1, -1}) {
            const double s = pos.s + sgn * shift;
            if (s >= 0 && s <= l.length()) out.push_back({int(li), s, legal_dir(l), true, shift + std::abs(pos.lateral)});
          }
      }
  } else if (region == "beyond") {
    beyond_candidates(lane, s0, dir, out);
  } else if (region == "front" || region == "back") {
    const int k = region == "back" ? -1 : 1;
    // Ahead of or behind a moving vehicle: a second's headway at its speed (at most 20 m), not
    // bumper to bumper.
    const double headway = a.speed_mps > 0.5 ? std::min(a.speed_mps * 1.0, 20.0) : 0.0;
    const bool parked = wants_parked(scene_.lanes.lanes()[size_t(lane)].for_stopping()) ||
                        (a.speed_mps == 0 && nothing_said_about_motion());
    for (const auto& [gap, cost] : gaps_from_anchor(base_gap, headway)) {
      const double s = s0 + k * dir * gap;
      if (s >= 0 && s <= scene_.lanes.lanes()[size_t(lane)].length()) out.push_back({lane, s, dir, parked, cost});
    }
  } else if (std::abs(std::sin(wrap(a.start.yaw - scene_.lanes.tangent_yaw_at(lane, s0)))) > 0.7) {
    beside_in_row(lane, s0, dir, region == "left" ? 1 : -1, out);
  } else {
    const double side = region == "left" ? 1 : -1;
    const Eigen::Vector2d left(-std::sin(a.start.yaw), std::cos(a.start.yaw));
    for (size_t li = 0; li < scene_.lanes.lanes().size(); ++li) {
      if (int(li) == lane) continue;
      const auto pos = scene_.lanes.project(int(li), ap);
      const double lateral = (scene_.lanes.point_at(int(li), pos.s) - ap).dot(left);
      if (side * lateral < 1.5 || side * lateral > 8) continue;
      const auto& l = scene_.lanes.lanes()[li];
      const bool parked = wants_parked(l.for_stopping()) || (a.speed_mps == 0 && nothing_said_about_motion());
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

// Whether a driving lane of the ego's way runs one lane width to `side` (+1 left) of `lane`,
// beside the ego.
bool Planner::same_way_lane_beside(int lane, int side) const {
  const auto pos = scene_.lanes.project(lane, ego_.p);
  const Eigen::Vector2d left_normal(-std::sin(ego_.yaw), std::cos(ego_.yaw));
  const Eigen::Vector2d q = scene_.lanes.point_at(lane, pos.s) + side * 3.5 * left_normal;
  for (const auto& at : scene_.lanes.containing(q, 0.3))
    if (at.lane != lane && scene_.lanes.lanes()[size_t(at.lane)].type == "driving" && same_way_as_ego(at.lane, at.s))
      return true;
  return false;
}

double Planner::lateral_of(int lane) const {  // signed ego-frame lateral offset of a lane near the ego
  const auto pos = scene_.lanes.project(lane, ego_.p);
  return ego_.to_ego(scene_.lanes.point_at(lane, pos.s)).y();
}

}  // namespace chatsim::agents::motion::detail
