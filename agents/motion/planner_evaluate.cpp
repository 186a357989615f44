#include "agents/motion/planner_impl.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include "agents/motion/car_following.hpp"

namespace chatsim::agents::motion::detail {
namespace {

// Why a turn asked for does not happen in the clip; nullopt for an action that is not a turn.
std::optional<std::string> turn_missing(const std::string& action) {
  if (action == "turn_left") return "the left turn does not fit in the clip from here";
  if (action == "turn_right") return "the right turn does not fit in the clip from here";
  return std::nullopt;
}

}  // namespace

double Planner::desired_speed(bool parked) const {
  if (parked) return 0;
  if (m_.speed_mps) return *m_.speed_mps;
  const std::string word = m_.speed.value_or("normal");
  if (m_.chase.value_or(false) && req_.anchor && !m_.speed) return std::max(req_.anchor->speed_mps, 4.0);
  // In a removed vehicle's place with no motion said: it moves as that vehicle did.
  if (m_.relative && m_.relative->region == "at" && req_.anchor && !m_.speed && !m_.action) return req_.anchor->speed_mps;
  if (m_.action == "backward") return word == "fast" ? 5.0 : word == "slow" ? 2.0 : 3.0;
  if (word == "ego") return ego_speed_ * m_.speed_factor.value_or(1.0);  // "twice as fast as me"
  return speed_for(word);
}

// The action made concrete (cut in, pull out, into the ego's lane, join: a lane change or a
// turn) and its path from the candidate's start; why not, when there is none.
std::optional<std::string> Planner::manoeuvre(const Candidate& c, double& speed, Manoeuvre& m) const {
  const double total = speed * (times_.back() + 1) + 20;
  const auto& map = scene_.lanes;
  if (m.action == "cut_in") {
    const double lat = ego_.to_ego(map.point_at(c.lane, c.s)).y();
    if (std::abs(lat) < 1.5) return std::string("cutting in needs a start in a lane beside the ego's");
    m.action = lat > 0 ? "lane_change_right" : "lane_change_left";
  }
  if (m.action == "straight" && speed > 0 && map.lanes()[size_t(c.lane)].for_stopping()) {
    // Moving off a parking lane: it pulls out into the driving lane beside it.
    if (const auto side = side_of_nearest_lane(c, true, 6.0))
      m.action = *side > 0 ? "lane_change_left" : "lane_change_right";
  }
  if (m.action == "lane_change_kerb" || m.action == "lane_change_median") {
    // The fast lane is on the side of the nearest lane running the other way (the left where
    // traffic keeps right, as assumed with none in reach); the kerb is on the other side.
    const int median = side_of_nearest_lane(c, false, 25.0).value_or(1);
    m.action = (m.action == "lane_change_median") == (median > 0) ? "lane_change_left" : "lane_change_right";
  }
  if (m.action == "lane_change_ego") {
    const double lat = ego_.to_ego(map.point_at(c.lane, c.s)).y();
    if (std::abs(lat) < 1.5) return std::string("it starts in the ego's lane already");
    m.action = lat > 0 ? "lane_change_right" : "lane_change_left";
  }
  if (m.action == "join") {  // out of a side street: the turn asked, else whichever reaches a lane
    const bool left = m.join_side != 0 ? m.join_side > 0 : turn_path(map, c.lane, c.s, c.dir, 1, total).has_value();
    m.action = left ? "turn_left" : "turn_right";
  }
  if (m.action.rfind("exit_", 0) == 0 && speed > 0) {  // the nth exit round a roundabout
    const int nth = m.action.back() - '0';
    auto round = roundabout_exit_path(map, c.lane, c.s, c.dir, nth, total);
    if (!round) return "no roundabout with a " + m.action.substr(5) + "th exit where its lane ends";
    // Said as the turn it makes: the way out against the way in.
    const double in_yaw = map.tangent_yaw_at(c.lane, c.s) + (c.dir > 0 ? 0 : kPi);
    const double turn = std::remainder(map.travel_yaw_at(map.find(round->target_lane), 0.0) - in_yaw, 2 * kPi);
    m.action = turn > kPi / 4 ? "turn_left" : turn < -kPi / 4 ? "turn_right" : "straight";
    m.path = std::move(round->path);
    m.connector = std::move(round->connector);
    return std::nullopt;
  }
  if (m.action == "static" || speed <= 0) {
    m.action = "static";
    speed = 0;
    m.path = lane_path(map, c.lane, c.s, c.dir, 1.0);
  } else if (m.action == "backward") {
    m.path = lane_path(map, c.lane, c.s, -c.dir, total);
    m.reverse_yaw = true;
  } else if (m.action == "turn_left" || m.action == "turn_right") {
    auto turn = turn_path(map, c.lane, c.s, c.dir, m.action == "turn_left" ? 1 : -1, total);
    if (!turn)
      return std::string("no crossing lane ahead to turn ") + (m.action == "turn_left" ? "left" : "right") +
             " into on the lane map";
    m.path = std::move(turn->path);
    m.connector = std::move(turn->connector);
  } else if (m.action == "lane_change_left" || m.action == "lane_change_right") {
    // Pulling out of a parking lane starts at once and turns out sharply (the car ahead is close).
    const bool pulling_out = map.lanes()[size_t(c.lane)].for_stopping();
    const double start = pulling_out ? 0.5 : std::max(4.0, speed * 1.0);
    const double length = pulling_out ? std::max(10.0, speed * 1.5) : std::max(15.0, speed * 3.0);
    auto lc = lane_change_path(map, c.lane, c.s, c.dir, m.action == "lane_change_left" ? 1 : -1, total, start, length);
    if (lc.target_lane.empty())
      return std::string("no lane to the ") + (m.action == "lane_change_left" ? "left" : "right") +
             " in the same direction to change into";
    m.path = std::move(lc.path);
  } else if (const auto corner = m_.action ? std::nullopt
                                            : turn_where_lane_ends(map, c.lane, c.s, c.dir,
                                                                   speed * times_.back() - 15, total)) {
    // Nothing said about its way and its road ends at a T it reaches and turns at within the
    // clip: round the corner, not off the map.
    m.action = corner->sign > 0 ? "turn_left" : "turn_right";
    m.path = std::move(corner->plan.path);
    m.connector = std::move(corner->plan.connector);
  } else {
    m.action = "straight";
    m.path = lane_path(map, c.lane, c.s, c.dir, total);
  }
  return std::nullopt;
}

// Pulling out into traffic that every start meets: the first of those starts from which, waiting
// for a gap (recorded traffic cannot make room; 1 s steps up to 80 % of the clip) and setting off
// from rest either way onto the road, it meets nobody. The shortest wait wins; a way whose turn no
// longer fits in the clip is not tried with a longer wait.
std::optional<std::pair<Candidate, Evaluated>> Planner::wait_for_gap(const std::vector<Candidate>& starts) const {
  std::vector<std::array<bool, 2>> too_late(starts.size(), {false, false});
  for (double wait = 0; wait <= times_.back() * 0.8; wait += 1)
    for (size_t k = 0; k < starts.size(); ++k)
      for (const int side : {1, -1}) {
        bool& late = too_late[k][side > 0 ? 0 : 1];
        if (late) continue;
        Evaluated e = evaluate_at(starts[k], desired_speed(starts[k].parked), wait, side);
        if (e.valid && e.first_collision < 0) return std::pair{starts[k], e};
        late = !e.valid;
      }
  return std::nullopt;
}

// With no speed said, a vehicle that faster traffic behind it would run into keeps that
// traffic's pace instead (recorded vehicles cannot brake for it).
Evaluated Planner::evaluate(const Candidate& c) const {
  Evaluated e = evaluate_at(c, desired_speed(c.parked));
  if (e.first_collision < 0 || m_.speed || m_.speed_mps || m_.chase.value_or(false) || e.action == "static") return e;
  const auto pace = pace_of_traffic_behind(e);
  // Not faster than a road allows: fast city traffic, or the ego's own pace on a motorway.
  if (!pace || *pace <= e.speed + 0.5 || *pace > std::max(speed_for("fast") * 1.5, ego_speed_ * 1.4)) return e;
  Evaluated faster = evaluate_at(c, *pace);
  return faster.valid && faster.first_collision < 0 ? faster : e;
}

// The speed of the vehicle that meets e's trajectory first, when it comes from behind.
std::optional<double> Planner::pace_of_traffic_behind(const Evaluated& e) const {
  const auto f = size_t(e.first_collision);
  for (const auto& ob : req_.obstacles) {
    if (ob.id != e.collides_with || f >= ob.poses.size() || f >= e.poses.size() || !ob.poses[f]) continue;
    const Pose2& me = e.poses[f];
    const Eigen::Vector2d to_ob(ob.poses[f]->x - me.x, ob.poses[f]->y - me.y);
    if (to_ob.dot(Eigen::Vector2d(std::cos(me.yaw), std::sin(me.yaw))) >= 0) return std::nullopt;  // ahead of it
    const size_t g = f > 0 && ob.poses[f - 1] ? f - 1 : f;
    const size_t h = g == f && f + 1 < ob.poses.size() && ob.poses[f + 1] ? f + 1 : f;
    if (g == h || h >= times_.size()) return std::nullopt;
    const double dt = times_[h] - times_[g];
    const Eigen::Vector2d d(ob.poses[h]->x - ob.poses[g]->x, ob.poses[h]->y - ob.poses[g]->y);
    return dt > 1e-6 ? std::optional<double>(d.norm() / dt) : std::nullopt;
  }
  return std::nullopt;
}

Evaluated Planner::evaluate_at(const Candidate& c, double speed, double wait_s, int join_side) const {
  Evaluated e;
  e.speed = speed;
  e.waits_s = wait_s;
  Manoeuvre mv;
  mv.action = c.parked ? "static" : m_.action.value_or("straight");
  mv.join_side = join_side;
  if (const auto why = manoeuvre(c, e.speed, mv)) return invalid(e, *why);
  std::string& action = mv.action;
  const Path& path = mv.path;
  const auto& connector = mv.connector;
  const bool reverse_yaw = mv.reverse_yaw;
  auto free_arc = arc_lengths_at(path, e.speed, times_, bend_accel());
  if (wait_s > 0) {  // standing at the start, then off from rest
    std::vector<double> after(times_.size());
    for (size_t f = 0; f < times_.size(); ++f) after[f] = std::max(0.0, times_[f] - wait_s);
    free_arc = arc_lengths_at(path, e.speed, after, bend_accel(), 2.5, true);
  }
  // Most starts of a turn far from its junction end here, before the steering is simulated.
  if (turn_out_of_reach(path, free_arc, action)) return invalid(e, *turn_missing(action));
  const bool follows = action != "static" && !reverse_yaw;
  e.poses = poses_along(path, follows ? follow_traffic(path, free_arc, e) : free_arc, action, reverse_yaw);
  if (wait_s > 0) e.slowed_to = -1;  // standing at the mouth by choice, not held up
  if (const auto why = action_missing(e.poses, action)) {
    // Held up behind traffic the action would not happen: plan it free, and let the collision
    // check say whom it meets.
    if (!follows || e.slowed_to < 0) return invalid(e, *why);
    e.slowed_to = -1;
    e.poses = poses_along(path, free_arc, action, reverse_yaw);
    if (const auto free_why = action_missing(e.poses, action)) return invalid(e, *free_why);
  }
  if (e.slowed_to >= 0 && action == "straight") try_overtake(c, e, action);
  // A vehicle that drives off the mapped lanes leaves the scene: its trajectory ends there.
  size_t keep = e.poses.size();
  int lane_hint = c.lane;
  const auto on_connector = [&](const Eigen::Vector2d& p) {
    return std::any_of(connector.begin(), connector.end(), [&](const Eigen::Vector2d& q) { return (q - p).norm() < 2.5; });
  };
  for (size_t f = 1; f < e.poses.size(); ++f) {
    const Eigen::Vector2d p(e.poses[f].x, e.poses[f].y);
    if (!scene_.lanes.on_some_lane(p, 0.3, lane_hint) && !on_connector(p)) {
      keep = f;
      break;
    }
  }
  if (keep < 2) return invalid(e, "it would leave the mapped lanes at once");
  e.truncated = keep < e.poses.size();
  e.poses.resize(keep);
  e.valid = true;
  e.action = action;
  for (size_t f = 0; f < e.poses.size() && e.first_collision < 0; ++f)
    for (const auto& ob : req_.obstacles) {
      if (f >= ob.poses.size() || !ob.poses[f]) continue;
      if (!boxes_overlap(e.poses[f], req_.size_lwh, *ob.poses[f], ob.size_lwh, 1.0, kClearanceM)) continue;
      if (ob.pedestrian) {
        if (e.crosses_pedestrian.empty()) e.crosses_pedestrian = ob.id;
        continue;
      }
      e.first_collision = int(f);
      e.collides_with = ob.id;
      break;
    }
  for (size_t f = 0; req_.ego && f < e.poses.size() && f < req_.ego->poses.size(); ++f)
    if (req_.ego->poses[f] &&
        boxes_overlap(e.poses[f], req_.size_lwh, *req_.ego->poses[f], req_.ego->size_lwh, 1.0, kClearanceM)) {
      e.meets_ego = int(f);
      break;
    }
  return e;
}

// The side (+1 left, -1 right) of the nearest driving lane within `reach` of a candidate's start
// that runs its way (same_way) or against it; none in reach: nullopt.
std::optional<int> Planner::side_of_nearest_lane(const Candidate& c, bool same_way, double reach) const {
  const auto& map = scene_.lanes;
  const Eigen::Vector2d p = map.point_at(c.lane, c.s);
  const double yaw = map.tangent_yaw_at(c.lane, c.s) + (c.dir > 0 ? 0 : kPi);
  const Eigen::Vector2d left(-std::sin(yaw), std::cos(yaw));
  std::optional<int> side;
  double best = reach;
  for (size_t i = 0; i < map.lanes().size(); ++i) {
    if (map.lanes()[i].type != "driving" || int(i) == c.lane) continue;
    const auto pos = map.project(int(i), p);
    const double along = std::cos(wrap(map.travel_yaw_at(int(i), pos.s) - yaw));
    if (std::abs(pos.lateral) >= best || (same_way ? along < 0.7 : along > -0.7)) continue;
    best = std::abs(pos.lateral);
    side = left.dot(map.point_at(int(i), pos.s) - p) > 0 ? 1 : -1;
  }
  return side;
}

// Held up behind slower traffic when the user asked for a speed: pass it in the lane beside,
// the user's way of driving (left first), when that lane lets it keep the speed.
void Planner::try_overtake(const Candidate& c, Evaluated& e, std::string& action) const {
  static const char* kLaneWords[] = {"ego", "left", "right", "oncoming", "parking", "cross"};
  const bool lane_asked = m_.lane && std::find(std::begin(kLaneWords), std::end(kLaneWords), *m_.lane) != std::end(kLaneWords);
  // A speed asked for ("fast", "80 km/h"), not "normally" or "slowly": those follow.
  const bool speed_asked = m_.speed_mps || m_.speed == "fast" || m_.speed == "faster";
  if (!speed_asked || lane_asked || (m_.action && *m_.action != "straight")) return;
  const double total = e.speed * (times_.back() + 1) + 20;
  for (int sign : {1, -1}) {
    if (!may_have_lane_beside(scene_.lanes, c.lane, c.s, c.dir, sign)) continue;
    // Out at once and briskly: the slower car ahead is what it is passing.
    const auto lc = lane_change_path(scene_.lanes, c.lane, c.s, c.dir, sign, total, 2.0, std::max(15.0, e.speed * 1.5));
    if (lc.target_lane.empty()) continue;
    Evaluated trial = e;
    trial.slowed_to = -1;
    trial.slow_penalty = 0;
    const auto arc = follow_traffic(lc.path, arc_lengths_at(lc.path, e.speed, times_, bend_accel()), trial);
    if (trial.slowed_to >= 0) continue;
    trial.poses = poses_along(lc.path, arc, "lane_change", false);
    if (action_missing(trial.poses, "lane_change")) continue;
    e = trial;
    action = sign > 0 ? "lane_change_left" : "lane_change_right";
    return;
  }
}

std::vector<Pose2> Planner::poses_along(const Path& path, const std::vector<double>& arc, const std::string& action,
                               bool reverse_yaw) const {
  if (action != "static" && !reverse_yaw) return bicycle_track(path, arc, times_);
  // Standing still, or reversing slowly along a straight lane: the path itself.
  std::vector<Pose2> poses;
  for (double q : arc) {
    const Eigen::Vector2d p = path.at(q);
    poses.push_back({p.x(), p.y(), wrap(path.yaw_at(q) + (reverse_yaw ? kPi : 0))});
  }
  return poses;
}

// Why the poses do not do the action within the clip, if they do not.
std::optional<std::string> Planner::action_missing(const std::vector<Pose2>& poses, const std::string& action) {
  const double turned = wrap(poses.back().yaw - poses.front().yaw) / kDeg;
  if ((action == "turn_left" && turned < 60) || (action == "turn_right" && turned > -60)) return turn_missing(action);
  if (action.rfind("lane_change", 0) == 0) {
    const double yaw0 = poses.front().yaw;
    const Eigen::Vector2d d(poses.back().x - poses.front().x, poses.back().y - poses.front().y);
    if (std::abs(-std::sin(yaw0) * d.x() + std::cos(yaw0) * d.y()) < 2.0)
      return "the lane change does not fit in the clip from here";
  }
  return std::nullopt;
}

// Sideways acceleration taken on bends: a driver asked to hurry takes them harder (about what a
// brisk driver does on a dry road), everyone else comfortably.
double Planner::bend_accel() const {
  const bool hurried = m_.speed == "fast" || m_.speed == "faster" || (m_.speed_mps && *m_.speed_mps > 12.0);
  return hurried ? 6.0 : 3.0;
}

bool Planner::turn_out_of_reach(const Path& path, const std::vector<double>& free_arc,
                                const std::string& action) const {
  if (!turn_missing(action) || free_arc.size() < 2) return false;
  double v_max = 0;
  for (size_t f = 0; f + 1 < free_arc.size(); ++f)
    v_max = std::max(v_max, (free_arc[f + 1] - free_arc[f]) / std::max(1e-6, times_[f + 1] - times_[f]));
  // Pure pursuit steers toward a point up to max(3 m, 0.9 v) ahead: it turns that much before
  // the path does. 5 m and 5 degrees more keep the test on the safe side of action_missing's.
  const double lead_m = std::max(3.0, 0.9 * v_max) + 5.0;
  return free_arc.back() + lead_m < arc_where_turned(path, free_arc.front(), 55.0);
}

// Slows behind whatever is ahead on the path (car following), and says when that costs much
// of the speed asked for.
std::vector<double> Planner::follow_traffic(const Path& path, const std::vector<double>& free_arc, Evaluated& e) const {
  std::vector<FollowedBox> others;
  for (const auto& ob : req_.obstacles) others.push_back({ob.size_lwh, &ob.poses});
  auto arc = follow_leaders(path, free_arc, times_, req_.size_lwh, others);
  const double span = times_.back() - times_.front();
  if (span > 0) {
    const double free_mean = (free_arc.back() - free_arc.front()) / span, mean = (arc.back() - arc.front()) / span;
    if (mean < 0.9 * free_mean) {
      e.slowed_to = mean;
      // A speed the user asked for weighs more than one left to the default.
      const double weight = (m_.speed || m_.speed_mps) ? 4.0 : 1.0;
      e.slow_penalty = weight * kSlowPenalty * (1 - mean / std::max(free_mean, 1e-6));
    }
  }
  return arc;
}

Evaluated Planner::invalid(Evaluated e, const std::string& why) {
  e.valid = false;
  e.invalid_reason = why;
  return e;
}

}  // namespace chatsim::agents::motion::detail
