#pragma once
// The motion planner's insides (not an API): planner.cpp searches the starts and answers,
// planner_candidates.cpp says where a vehicle may start, planner_evaluate.cpp how it drives
// from there (path, speed, car following, overtaking, collisions).
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "agents/motion/planner.hpp"

namespace chatsim::agents::motion::detail {

constexpr double kPi = std::numbers::pi;
// Score a start loses for being held up behind traffic: all of it lost weighs as much as a
// start 30 m from the distance asked for.
constexpr double kSlowPenalty = 30.0;
// A start further from its anchor than the distance said: worse than the most a wait behind
// traffic costs (4 kSlowPenalty for a speed said).
constexpr double kDistanceMissedPenalty = 4 * kSlowPenalty;
// How far a start may be from a distance said ("20 m ahead", "20 m behind the van") and still be
// that distance.
inline double distance_tolerance(double said_m) { return std::max(3.0, 0.2 * said_m); }
// Clearance kept from every other box (each side): recorded vehicles pass a kerbside cone at
// less than half a metre.
constexpr double kClearanceM = 0.15;
// How far off every lane a vehicle to place by may stand and still lend its nearest lane.
constexpr double kOffLaneReachM = 12.0;
// Score a start loses for driving off the mapped lanes before the clip ends.
constexpr double kLeavesMapPenalty = 10.0;
// Score a start loses when the recording car's path runs into it: a tie-breaker, less than the
// ego's direction unsaid (8): a heavier one turned vehicles round to dodge the ego (experiments.md).
constexpr double kMeetsEgoPenalty = 6.0;
constexpr double kDeg = kPi / 180;

inline double wrap(double a) { return std::remainder(a, 2 * kPi); }
inline Eigen::Vector2d dir_of(double yaw) { return {std::cos(yaw), std::sin(yaw)}; }

// The ego at frame 0: the frame positions and regions are spoken in.
struct EgoFrame {
  Eigen::Vector2d p;
  double yaw = 0;
  Eigen::Vector2d to_ego(const Eigen::Vector2d& world) const {
    const Eigen::Vector2d d = world - p;
    return {std::cos(yaw) * d.x() + std::sin(yaw) * d.y(), -std::sin(yaw) * d.x() + std::cos(yaw) * d.y()};
  }
};
EgoFrame ego_frame(const scene::Scene& scene);

struct Region {
  double a_min = -180, a_max = 180;  // degrees, ego frame 0
  bool back = false;                 // |angle| >= a_min instead
  double d_min = 0, d_max = 1e9, d_pref = 15;
};
Region region_for(const std::string& placement, const MotionIntent& m, double widen = 1.0);
bool in_region(const Region& r, const Eigen::Vector2d& pe);
// Each camera's horizontal field of view as bearings in the ego frame (degrees, left positive),
// and how many degrees a point in the ego frame lies outside all of them (0: some camera sees it).
std::vector<std::pair<double, double>> camera_bearings(const scene::Scene& scene);
double degrees_out_of_sight(const std::vector<std::pair<double, double>>& bearings, const Eigen::Vector2d& pe);

// A start placed by the ego's road rather than its axis: metres along the road from the ego
// (ahead or behind, as the region says) and sideways from the ego's lane.
struct RoadPlace {
  double along = 0, lateral = 0;
};

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
  double slowed_to = -1;     // >= 0: traffic ahead holds it to this mean speed (m/s), well below the asked one
  double slow_penalty = 0;   // added to the candidate's score for the speed lost behind traffic
  std::string crosses_pedestrian;  // a pedestrian's recorded path runs through it (said in a note)
  double waits_s = 0;        // stands at its start this long, then sets off from rest (a gap to join)
  int meets_ego = -1;        // frame where the recording car's box meets it, -1: never
};

inline int legal_dir(const scene::Lane& lane) { return lane.direction == scene::TrafficDirection::Backward ? -1 : 1; }

// What a vehicle does from a start, made concrete: the action and the path it drives.
struct Manoeuvre {
  std::string action;
  Path path;
  std::vector<Eigen::Vector2d> connector;  // a turn's junction curve: on the road even where unmapped
  bool reverse_yaw = false;                // backing up: the body faces against the path
  int join_side = 0;                       // joining a road: +1 turn left, -1 right, 0 left where it can
};

class Planner {
 public:
  Planner(const scene::Scene& scene, const PlanRequest& req);
  PlanResult run();

 private:
  PlanResult run_once();
  bool starts_inside_another(const Candidate& c) const;
  bool same_way_lane_beside(int lane, int side) const;
  static std::string fmt(double v);
  bool nothing_said_about_motion() const;
  bool wants_parked(bool on_parking) const;
  bool same_way_as_ego(int lane, double s) const;
  // The lane said and the lane's use said, for a start travelling dir (0: the lane's legal way).
  double lane_hint_penalty(int lane, double s, int dir = 0) const;
  double said_lane_penalty(int lane, double s, int dir = 0) const;
  std::string lane_said() const;  // for notes: "bus", "left", "inner"
  std::vector<double> lane_edge_penalties() const;

  // Direction checks and preferences for one candidate travelling dir on lane.
  std::optional<double> direction_score(int lane, double s, int dir, bool parked) const;
  std::vector<Candidate> region_candidates() const;
  std::vector<Candidate> region_candidates(bool moving_on_parking) const;
  bool stopping_lane_in(const Region& region) const;  // some parking lane or shoulder lies in it
  // Where the ego's road bends away from its axis: a point beside that road ahead (or behind) by
  // the region's distance, which the angle window would miss.
  std::optional<RoadPlace> bend_place(const Eigen::Vector2d& world, const Region& region,
                                      const std::string& placement) const;
  Region search_region(const std::string& placement, double widen) const;
  void place_by_junction(const std::string& placement, double widen, Region& region) const;
  std::vector<Candidate> relative_candidates() const;
  void beside_in_row(int lane, double s0, int dir, int side, std::vector<Candidate>& out) const;
  void opposite_candidates(std::vector<Candidate>& out) const;
  void beyond_candidates(int lane, double s0, int dir, std::vector<Candidate>& out) const;
  // Centre-to-centre gaps to try ahead of or behind the anchor, each with its cost: near the
  // distance said ("20 m ahead of the van"), else as close as a headway allows.
  std::vector<std::pair<double, double>> gaps_from_anchor(double base_gap, double headway) const;
  // The closest a start may be to the anchor, centre to centre: bumper to bumper plus 2 m.
  double anchor_base_gap() const;
  double desired_speed(bool parked) const;
  Evaluated evaluate(const Candidate& c) const;
  Evaluated evaluate_at(const Candidate& c, double speed, double wait_s = 0, int join_side = 0) const;
  std::optional<double> pace_of_traffic_behind(const Evaluated& e) const;
  std::optional<std::string> manoeuvre(const Candidate& c, double& speed, Manoeuvre& m) const;
  std::optional<std::pair<Candidate, Evaluated>> wait_for_gap(const std::vector<Candidate>& starts) const;

  // The side (+1 left, -1 right) of the nearest driving lane within reach running the candidate's
  // way (a parking start pulls out into it) or against it (the fast lane lies on that side).
  std::optional<int> side_of_nearest_lane(const Candidate& c, bool same_way, double reach) const;

  // Held up behind slower traffic when the user asked for a speed: pass it in the lane beside,
  // the user's way of driving (left first), when that lane lets it keep the speed.
  void try_overtake(const Candidate& c, Evaluated& e, std::string& action) const;
  std::vector<Pose2> poses_along(const Path& path, const std::vector<double>& arc, const std::string& action, bool reverse_yaw) const;

  // Why the poses do not do the action within the clip, if they do not.
  static std::optional<std::string> action_missing(const std::vector<Pose2>& poses, const std::string& action);
  double bend_accel() const;  // m/s^2 sideways on bends
  // Whether a turn's bend lies beyond the farthest the free-flow profile reaches in the clip.
  bool turn_out_of_reach(const Path& path, const std::vector<double>& free_arc, const std::string& action) const;

  // Slows behind whatever is ahead on the path (car following), and says when that costs much
  // of the speed asked for.
  std::vector<double> follow_traffic(const Path& path, const std::vector<double>& free_arc, Evaluated& e) const;
  static Evaluated invalid(Evaluated e, const std::string& why);
  PlanResult finish(const Candidate& c, const Evaluated& e, PlanResult result) const;
  PlanResult plan_without_lanes() const;
  // Parked in a removed vehicle's place where no lane runs ("park a van where the truck was"):
  // standing at its pose; nullopt when a lane runs there or it should not stand.
  std::optional<PlanResult> parked_off_lane() const;
  double lateral_of(int lane) const;  // signed ego-frame lateral offset of a lane near the ego

  std::string describe_placement() const { return m_.placement.value_or("front"); }

  const scene::Scene& scene_;
  const PlanRequest& req_;
  MotionIntent m_;
  EgoFrame ego_;
  std::vector<double> times_;
  bool movable_ = true;
  int ego_lane_ = -1;
  double ego_lane_s_ = 0;   // the ego's arc length on it
  int ego_lane_dir_ = 1;    // +1: the ego drives along the centreline's order
  double widen_ = 1.0;     // distance tolerance factor (see run)
  bool collided_ = false;  // the last run_once accepted a collision
  mutable bool lane_missed_ = false;  // the last run_once's start is not on the lane asked for
  double ego_speed_ = 0;              // the ego's mean recorded speed over the clip, m/s
  std::vector<bool> lane_beside_;     // "the left/right lane": a same-way lane beside each lane, that side
  std::vector<int> use_lanes_;        // "the bus lane": the lanes of the use said (lane_names.hpp)
  std::vector<int> reserved_lanes_;   // bus, tram and cycle lanes this vehicle may not use unless told
  std::optional<scene::LaneMap::JunctionSpan> junction_;  // "past the junction": the first one ahead
  std::vector<bool> branch_;          // with "the left/right lane": each lane a pocket or a ramp
  int oncoming_side_ = 0;             // with "the oncoming lane": its side of the ego (+1 left), 0 none
};

}  // namespace chatsim::agents::motion::detail
