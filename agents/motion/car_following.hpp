#pragma once
// Car following for added vehicles: the Intelligent Driver Model (Treiber, Hennecke and Helbing,
// 2000) along the vehicle's path, with every other road user that stands on that path ahead as
// a possible leader. A vehicle put behind a slower one slows down behind it instead of driving
// through it.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "agents/motion/path.hpp"

namespace chatsim::agents::motion {

// Another road user's box per frame, as the planner's obstacles give them (nullopt: absent).
struct FollowedBox {
  Eigen::Vector3d size_lwh;
  const std::vector<std::optional<Pose2>>* poses;
};

struct IdmParams {
  double max_accel = 1.5;      // m/s^2
  double comfort_brake = 2.0;  // m/s^2
  double min_gap = 2.0;        // m, bumper to bumper at rest
  double headway_s = 1.2;      // s
};

// Arc lengths along `path` at `times` (one per frame): free_arc is the free-flow profile
// (arc_lengths_at), which IDM follows as its desired speed, slowed for leaders on the path.
// own_size: the vehicle's box. Leaders are boxes whose centre lies on the path ahead, within
// half the two widths sideways.
std::vector<double> follow_leaders(const Path& path, const std::vector<double>& free_arc, const std::vector<double>& times,
                                   const Eigen::Vector3d& own_size, const std::vector<FollowedBox>& others,
                                   const IdmParams& params = {});

}  // namespace chatsim::agents::motion
