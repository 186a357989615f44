#pragma once
// Geometric paths for the motion planner: lane following, turns at crossings, lane changes,
// and a speed profile that keeps lateral and longitudinal acceleration feasible.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/scene/lane_map.hpp"

namespace chatsim::agents::motion {

struct Pose2 {
  double x = 0, y = 0, yaw = 0;
};

// A polyline with arc length; yaw is the direction of travel along it.
struct Path {
  std::vector<Eigen::Vector2d> points;
  std::vector<double> s;
  void push(const Eigen::Vector2d& p);
  double length() const { return s.empty() ? 0 : s.back(); }
  Eigen::Vector2d at(double s) const;
  double yaw_at(double s) const;
  double curvature_at(double s) const;
};

// Follows the lane's centreline from s0 in direction dir (+1 along the polyline, -1 against),
// for `length` metres, continuing straight past the lane's end.
Path lane_path(const scene::LaneMap& map, int lane, double s0, int dir, double length, double step = 0.5);

// Appends a cubic Hermite curve from the path's end to `to` with end heading `to_yaw`.
void append_hermite(Path& path, const Eigen::Vector2d& to, double to_yaw, double step = 0.5);

struct TurnPlan {
  Path path;
  std::string target_lane;
  // The curve joining the two lanes: at a junction the map may leave it unmapped (lanes end at
  // the kerb), but the turn drives there.
  std::vector<Eigen::Vector2d> connector;
};
// Along the lane from s0 in direction dir, the next crossing with a lane whose legal travel
// turns left (sign +1) or right (sign -1) by roughly 90 degrees; the path turns onto it.
std::optional<TurnPlan> turn_path(const scene::LaneMap& map, int lane, double s0, int dir, int sign, double length);
// Where the lane ends within `reach` at a road across it with no lane going on straight (a T
// junction): the turn into that road's nearer lane, a path of `length`; sign +1 left, -1 right.
struct RoadEndTurn {
  int sign = 0;
  TurnPlan plan;
};
std::optional<RoadEndTurn> turn_where_lane_ends(const scene::LaneMap& map, int lane, double s0, int dir, double reach,
                                                 double length);
// The nth exit (1-based, in the ring's direction) of the roundabout the lane runs into, if any.
std::optional<TurnPlan> roundabout_exit_path(const scene::LaneMap& map, int lane, double s0, int dir, int nth,
                                             double length);

struct LaneChangePlan {
  Path path;
  std::string target_lane;   // empty: no lane there, moved by one lane width
};
// Whether a driving lane running the same way may lie one lane to the left (sign +1) or right
// (-1) of the lane at s0: a looser test than lane_change_path's, and without building a path.
bool may_have_lane_beside(const scene::LaneMap& map, int lane, double s0, int dir, int sign);
// Follows the lane, then moves smoothly one lane to the left (sign +1) or right (-1).
LaneChangePlan lane_change_path(const scene::LaneMap& map, int lane, double s0, int dir, int sign, double length,
                                double start_after_m, double change_length_m);

// Positions along the path at the given times, driving at up to v_desired with lateral
// acceleration at most a_lat and starting at the allowed speed, or from rest.
std::vector<double> arc_lengths_at(const Path& path, double v_desired, const std::vector<double>& times,
                                   double a_lat = 3.0, double a_long = 2.5, bool from_rest = false);

// The first arc length past `from` where the path heads at least `degrees` away from its
// heading at `from`; infinity when it never does.
double arc_where_turned(const Path& path, double from, double degrees);

// Drives the path with a kinematic bicycle (wheelbase, steering angle and steering rate
// limits) following a pure-pursuit controller whose reference moves along the path as
// `arc` says at `times`; returns the vehicle's poses at those times (yaw = body heading).
std::vector<Pose2> bicycle_track(const Path& path, const std::vector<double>& arc, const std::vector<double>& times,
                                 double wheelbase_m = 2.8, double max_steer_rad = 0.6, double max_steer_rate = 0.8);

}  // namespace chatsim::agents::motion
