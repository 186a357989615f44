#pragma once
// The motion agent's role functions: choose a start on the lane map that matches the intent
// (region, distance, lane, direction) and is free of collisions with every other vehicle over
// the whole clip, then plan a feasible trajectory for the scene's frame times.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "agents/motion/motion_intent.hpp"
#include "agents/motion/path.hpp"
#include "common/scene/scene.hpp"

namespace chatsim::agents::motion {

// Another road user: its box at each frame (nullopt where it is not in the scene).
struct Obstacle {
  std::string id;
  Eigen::Vector3d size_lwh;
  std::vector<std::optional<Pose2>> poses;
  // A pedestrian: crossing its recorded path is said in a note, not a reason to refuse (a person
  // steps round a parked car; the recording cannot show it).
  bool pedestrian = false;
};

// Where a vehicle added earlier starts, for "in front of the added car".
struct Anchor {
  Pose2 start;              // world
  Eigen::Vector3d size_lwh;
  double speed_mps = 0;
  bool wrong_way = false;
};

struct PlanRequest {
  MotionIntent intent;
  Eigen::Vector3d size_lwh{4.5, 1.9, 1.5};
  std::string type = "car";           // cones and barriers never move
  std::vector<Obstacle> obstacles;
  std::optional<Anchor> anchor;       // required when intent.relative is set
  bool strict = false;                // fail rather than accept a collision
  std::optional<double> ego_speed_mps;  // the ego's speed when a view change sets it, else recorded
  // The recording car on its recorded path (ego_obstacle): it cannot give way, so a start it
  // would meet loses score and, kept, is said in a note. None when the view changes its motion.
  std::optional<Obstacle> ego;
};

struct PlanResult {
  bool ok = false;
  std::string reason;                 // when not ok: why, for the user
  std::vector<Pose2> trajectory;      // world, one per frame (fewer if it leaves the lane map)
  std::vector<double> t_s;            // frame times from frame 0
  MotionIntent resolved;              // the intent with every default filled in
  std::string lane;                   // start lane id ("" without a lane map)
  double speed_mps = 0;
  std::vector<std::string> notes;     // what the user should know (e.g. an unavoidable collision)
  std::vector<std::string> not_done;  // parts of the request it could not do, with why
};

// The obstacles a scene's labelled objects make, minus the removed ones.
std::vector<Obstacle> scene_obstacles(const scene::Scene& scene, const std::vector<std::string>& removed);
Obstacle trajectory_obstacle(const std::string& id, const Eigen::Vector3d& size_lwh, const std::vector<Pose2>& trajectory);
// The recording car itself along its recorded path (id "ego"): a passenger car's box, its centre
// ahead of a rear-axle origin.
Obstacle ego_obstacle(const scene::Scene& scene);

PlanResult plan_motion(const scene::Scene& scene, const PlanRequest& request);

// Do two boxes overlap (2D, oriented)? `shrink` scales both boxes (0.9 = 10 % smaller).
bool boxes_overlap(const Pose2& a, const Eigen::Vector3d& size_a, const Pose2& b, const Eigen::Vector3d& size_b,
                   double shrink = 1.0, double margin = 0.0);

double speed_for(const std::string& word);  // slow, normal, fast -> m/s

}  // namespace chatsim::agents::motion
