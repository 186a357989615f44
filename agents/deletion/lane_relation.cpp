#include "agents/deletion/lane_relation.hpp"

#include <cmath>
#include <numbers>

namespace chatsim::agents::deletion {
namespace {

// Whether a lane of the same carriageway lies on that side (+1 left, -1 right) of one of width
// own_width: lane by lane, each abutting the last (a service road past a verge is another road).
bool lane_next_to(const std::vector<std::pair<double, double>>& beside, double own_width, int side) {
  for (const auto& [offset, width] : beside)
    if (side * offset > 0 && side * offset <= (own_width + width) / 2 + 1.0) return true;
  return false;
}

constexpr double kPi = std::numbers::pi;
double wrap(double a) { return std::remainder(a, 2 * kPi); }

// The driving lane with the smallest offset from p among those p lies on, or -1.
int lane_at(const scene::LaneMap& lanes, const Eigen::Vector2d& p, bool driving_only) {
  int best = -1;
  double best_lat = 1e9;
  for (const auto& pos : lanes.containing(p, 0.3)) {
    if (driving_only && lanes.lanes()[size_t(pos.lane)].type != "driving") continue;
    if (std::abs(pos.lateral) < best_lat) {
      best_lat = std::abs(pos.lateral);
      best = pos.lane;
    }
  }
  return best;
}

// The half of the road a place off the driving lanes belongs to: that of the nearest driving lane
// along it, when the road has lanes both ways.
template <typename SameWay>
void road_side_by_nearest_lane(const scene::LaneMap& lanes, const Eigen::Vector2d& p, const SameWay& same_way,
                               LaneRelation& r) {
  int nearest = -1;
  double best = 8.0;
  bool road_has_oncoming = false;
  for (size_t i = 0; i < lanes.lanes().size(); ++i) {
    if (lanes.lanes()[i].type != "driving") continue;
    const auto pos = lanes.project(int(i), p);
    if (pos.s <= 0.5 || pos.s >= lanes.lanes()[i].length() - 0.5 || std::abs(pos.lateral) > 20) continue;
    const double d = same_way(int(i), pos.s);
    if (d > kPi / 4 && d < 3 * kPi / 4) continue;  // a side street
    road_has_oncoming = road_has_oncoming || d >= 3 * kPi / 4;
    if (std::abs(pos.lateral) < best) {
      best = std::abs(pos.lateral);
      nearest = int(i);
    }
  }
  if (nearest < 0 || !road_has_oncoming) return;
  const bool far = same_way(nearest, lanes.project(nearest, p).s) >= 3 * kPi / 4;
  r.far_side = far;
  r.near_side = !far;
}

}  // namespace

LaneRelation lane_relation(const scene::Scene& scene, const Eigen::Vector2d& p) {
  LaneRelation r;
  const auto& lanes = scene.lanes;
  if (lanes.empty() || scene.frames.empty()) return r;
  const int own = lane_at(lanes, p, false);
  r.own = own;
  const auto& ego_pose = scene.frames.front().ego_to_world;
  const Eigen::Vector2d ego = ego_pose.translation().head<2>();
  const Eigen::Vector3d fwd = ego_pose.linear().col(0);
  const int ego_lane = lane_at(lanes, ego, true);
  // The ego's direction of travel where the object is: along the ego's lane (roads curve).
  double ref_yaw = std::atan2(fwd.y(), fwd.x());
  if (ego_lane >= 0) ref_yaw = lanes.travel_yaw_at(ego_lane, lanes.project(ego_lane, p).s);
  const auto same_way = [&](int lane, double s) { return std::abs(wrap(lanes.travel_yaw_at(lane, s) - ref_yaw)); };
  if (own < 0) {
    // Off every lane but close beside a driving one: the shoulder (or a pavement), on its side.
    for (const auto& pos : lanes.containing(p, 3.0))
      if (lanes.lanes()[size_t(pos.lane)].type == "driving") r.shoulder = true;
    road_side_by_nearest_lane(lanes, p, same_way, r);
    return r;
  }
  if (lanes.lanes()[size_t(own)].for_stopping()) {  // a parking lane, or a map that draws the hard shoulder
    (lanes.lanes()[size_t(own)].type == "parking" ? r.parking : r.shoulder) = true;
    road_side_by_nearest_lane(lanes, p, same_way, r);
    return r;
  }
  const double d = same_way(own, lanes.project(own, p).s);
  if (d > 3 * kPi / 4) {
    r.oncoming = true;
    r.far_side = true;
    return r;
  }
  if (d > kPi / 4) {
    r.cross = true;
    return r;
  }
  r.ego = own == ego_lane;
  r.near_side = true;
  if (lanes.merges(own) || lanes.diverges(own) != 0) {  // an on-ramp or an exit: not one of the road's own lanes
    r.ramp = true;
    return r;
  }
  // Same-direction driving lanes beside the object's, by which side of it they lie.
  int oncoming_side = 0;
  const double own_yaw = lanes.travel_yaw_at(own, lanes.project(own, p).s);
  const Eigen::Vector2d own_left(-std::sin(own_yaw), std::cos(own_yaw));
  std::vector<std::pair<double, double>> beside;  // same-way lanes beside: offset (+ left), width
  for (size_t i = 0; i < lanes.lanes().size(); ++i) {
    if (int(i) == own || lanes.lanes()[i].type != "driving") continue;
    const auto pos = lanes.project(int(i), p);
    // Which side the other way's traffic passes on (+1 left): the fast lane is the one next to it.
    if (std::abs(pos.lateral) <= 25 && pos.s > 0.5 && pos.s < lanes.lanes()[i].length() - 0.5 &&
        same_way(int(i), pos.s) > 3 * kPi / 4)
      oncoming_side = own_left.dot(lanes.point_at(int(i), pos.s) - p) > 0 ? 1 : -1;
    if (std::abs(pos.lateral) > 12 || same_way(int(i), pos.s) > kPi / 4) continue;
    if (pos.s <= 0.5 || pos.s >= lanes.lanes()[i].length() - 0.5) continue;  // beside it, not beyond its end
    if (std::abs(pos.lateral) > 1.5) beside.emplace_back(-pos.lateral, lanes.lanes()[i].width);
  }
  const double own_width = lanes.lanes()[size_t(own)].width;
  r.left = !lane_next_to(beside, own_width, +1);
  r.right = !lane_next_to(beside, own_width, -1);
  // With no other way's lanes beside (a one-way street), the fast lane is on the left.
  r.inner = oncoming_side < 0 ? r.right : r.left;
  r.outer = oncoming_side < 0 ? r.left : r.right;
  r.middle = !r.left && !r.right;
  return r;
}

namespace {

// Driving lanes within `reach` of p running along (|cos| > 0.7) or across (|cos| < 0.5) `yaw`.
int lanes_near(const scene::LaneMap& lanes, const Eigen::Vector2d& p, double yaw, double reach, bool across) {
  int n = 0;
  for (size_t i = 0; i < lanes.lanes().size(); ++i) {
    if (lanes.lanes()[i].type != "driving") continue;
    const auto pos = lanes.project(int(i), p);
    if (pos.s <= 0 || pos.s >= lanes.lanes()[i].length() || std::abs(pos.lateral) > reach) continue;
    const double c = std::abs(std::cos(pos.tangent_yaw - yaw));
    n += across ? c < 0.5 : c > 0.7;
  }
  return n;
}

}  // namespace

std::string main_road(const scene::Scene& scene) {
  if (scene.lanes.empty() || scene.frames.empty()) return "road";
  const auto& pose = scene.frames.front().ego_to_world;
  const Eigen::Vector2d ego = pose.translation().head<2>();
  const double yaw = std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
  const auto junction = scene.lanes.junction_ahead(ego, yaw);
  if (!junction) return "road";
  const Eigen::Vector2d at = ego + (junction->from + junction->to) / 2 * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
  return lanes_near(scene.lanes, at, yaw, 15, true) > lanes_near(scene.lanes, ego, yaw, 12, false) ? "cross" : "road";
}

bool has_lane(const LaneRelation& r, const std::string& lane) {
  if (lane == "road") return r.own >= 0 && !r.cross && !r.parking && !r.shoulder;
  if (lane == "ego") return r.ego;
  if (lane == "left") return r.left;
  if (lane == "middle") return r.middle;
  if (lane == "right") return r.right;
  if (lane == "inner") return r.inner;
  if (lane == "outer") return r.outer;
  if (lane == "oncoming") return r.oncoming;
  if (lane == "cross") return r.cross;
  if (lane == "parking") return r.parking;
  if (lane == "ramp") return r.ramp;
  if (lane == "shoulder") return r.shoulder;
  if (lane == "near") return r.near_side;
  if (lane == "far") return r.far_side;
  return false;
}

}  // namespace chatsim::agents::deletion
