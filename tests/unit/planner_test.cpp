// The motion planner on a synthetic lane map: placements, actions, collisions, no lane map.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "agents/motion/planner.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim::agents::motion;

namespace {

PlanResult plan(const chatsim::scene::Scene& s, const std::string& instruction, const std::string& type = "car") {
  PlanRequest req;
  req.intent = parse_motion(instruction);
  req.type = type;
  req.obstacles = scene_obstacles(s, {});
  return plan_motion(s, req);
}

double heading_change_deg(const std::vector<Pose2>& t) {
  double total = 0;
  for (size_t i = 1; i < t.size(); ++i) total += std::remainder(t[i].yaw - t[i - 1].yaw, 2 * M_PI);
  return total * 180 / M_PI;
}

bool collides(const PlanResult& r, const std::vector<Obstacle>& obstacles, const Eigen::Vector3d& size) {
  for (size_t f = 0; f < r.trajectory.size(); ++f)
    for (const auto& o : obstacles)
      if (f < o.poses.size() && o.poses[f] && boxes_overlap(r.trajectory[f], size, *o.poses[f], o.size_lwh))
        return true;
  return false;
}

}  // namespace

TEST(Planner, FrontMeansAheadInTheEgoLaneMovingAway) {
  const auto s = test_support::synthetic_scene();
  const auto r = plan(s, "a car 15 m in front of me");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "ego");
  EXPECT_NEAR(r.trajectory[0].x, 15, 1.5);
  EXPECT_GT(r.trajectory.back().x, r.trajectory[0].x + 30);  // ~8 m/s for 5 s
  EXPECT_EQ(r.resolved.direction, "away");
  EXPECT_FALSE(collides(r, scene_obstacles(s, {}), {4.5, 1.9, 1.5}));
}

TEST(Planner, TowardMeUsesTheOncomingLaneUnlessWrongWay) {
  const auto s = test_support::synthetic_scene();
  auto r = plan(s, "a car 25 m ahead driving toward me");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "oncoming");
  EXPECT_FALSE(r.resolved.wrong_way.value_or(true));
  r = plan(s, "a car driving the wrong way toward me in my lane");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "ego");
  EXPECT_TRUE(r.resolved.wrong_way.value_or(false));
  EXPECT_LT(r.trajectory.back().x, r.trajectory.front().x);
}

TEST(Planner, TurnsAtTheCrossingWithFeasibleCurvature) {
  const auto s = test_support::synthetic_scene();
  auto r = plan(s, "a car 40 m ahead that turns left");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_GT(heading_change_deg(r.trajectory), 60);
  // Lateral acceleration stays within what a car does (speed limited in the curve).
  for (size_t i = 1; i + 1 < r.trajectory.size(); ++i) {
    const double v = std::hypot(r.trajectory[i + 1].x - r.trajectory[i].x, r.trajectory[i + 1].y - r.trajectory[i].y) / 0.1;
    const double w = std::remainder(r.trajectory[i + 1].yaw - r.trajectory[i].yaw, 2 * M_PI) / 0.1;
    EXPECT_LT(std::abs(v * w), 4.5) << "frame " << i;
  }
  r = plan(s, "a car 40 m ahead that turns right");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_LT(heading_change_deg(r.trajectory), -60);
}

TEST(Planner, LaneChangeMovesOneLane) {
  const auto s = test_support::synthetic_scene();
  const auto r = plan(s, "a car 10 m ahead changing lanes to the left");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_NEAR(r.trajectory.back().y - r.trajectory.front().y, 3.5, 0.3);
  EXPECT_NEAR(r.trajectory.back().yaw, 0, 0.1);
}

TEST(Planner, AvoidsParkedAndMovingVehicles) {
  const auto s = test_support::synthetic_scene();
  // The parked red car stands at x=20 on the parking lane: a parked car 20 m ahead on the right moves aside.
  const auto r = plan(s, "a parked car on the right 20 m ahead");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "parking");
  EXPECT_FALSE(collides(r, scene_obstacles(s, {}), {4.5, 1.9, 1.5}))
      << "start x " << r.trajectory[0].x << " y " << r.trajectory[0].y << (r.notes.empty() ? "" : r.notes[0]);
  EXPECT_EQ(r.resolved.action, "static");
}

TEST(Planner, NoTurnWithoutACrossingIsAClearRefusal) {
  auto s = test_support::synthetic_scene();
  std::vector<chatsim::scene::Lane> straight(s.lanes.lanes().begin(), s.lanes.lanes().begin() + 4);
  s.lanes = chatsim::scene::LaneMap(straight);
  const auto r = plan(s, "a car ahead that turns left");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("turn left"), std::string::npos) << r.reason;
}

TEST(Planner, WithoutALaneMapPlansStraightAndSaysSo) {
  const auto s = test_support::synthetic_scene(false);
  const auto r = plan(s, "a car 20 m ahead that turns left");
  ASSERT_TRUE(r.ok);
  EXPECT_NEAR(r.trajectory[0].x, 20, 1e-6);
  ASSERT_FALSE(r.not_done.empty());
  EXPECT_NE(r.not_done[0].find("no lane map"), std::string::npos);
}

TEST(Planner, ConesNeverMove) {
  const auto s = test_support::synthetic_scene();
  const auto r = plan(s, "a cone 12 m ahead driving fast", "cone");
  ASSERT_TRUE(r.ok);
  EXPECT_DOUBLE_EQ(r.trajectory.front().x, r.trajectory.back().x);
}

TEST(Planner, BoxOverlap) {
  const Eigen::Vector3d car(4, 2, 1.5);
  EXPECT_TRUE(boxes_overlap({0, 0, 0}, car, {3.9, 0, 0}, car));
  EXPECT_FALSE(boxes_overlap({0, 0, 0}, car, {4.1, 0, 0}, car));
  EXPECT_FALSE(boxes_overlap({0, 0, 0}, car, {3.9, 0, 0}, car, 0.9));
  EXPECT_TRUE(boxes_overlap({0, 0, 0}, car, {0, 0, M_PI / 2}, car));
}

// The trajectory is what a kinematic bicycle can drive: yaw rate within v * tan(max steer) / L,
// and the tracker ends the turn on the lane it turned into.
TEST(Planner, TrajectoriesAreDrivableByABicycleModel) {
  const auto s = test_support::synthetic_scene();
  const auto r = plan(s, "a car 40 m ahead that turns right");
  ASSERT_TRUE(r.ok) << r.reason;
  for (size_t i = 1; i < r.trajectory.size(); ++i) {
    const double dt = r.t_s[i] - r.t_s[i - 1];
    const double v = std::hypot(r.trajectory[i].x - r.trajectory[i - 1].x, r.trajectory[i].y - r.trajectory[i - 1].y) / dt;
    const double yaw_rate = std::abs(std::remainder(r.trajectory[i].yaw - r.trajectory[i - 1].yaw, 2 * M_PI)) / dt;
    EXPECT_LE(yaw_rate, v * std::tan(0.6) / 2.8 + 0.05) << "frame " << i;
  }
  const auto& end = r.trajectory.back();
  const auto on = s.lanes.containing({end.x, end.y});
  ASSERT_FALSE(on.empty());
  EXPECT_EQ(s.lanes.lanes()[size_t(on.front().lane)].id, "south");
  EXPECT_LT(std::abs(on.front().lateral), 1.0);
}

TEST(Planner, TheLaneNextToTheCentreLineOrTheKerb) {
  const auto s = test_support::synthetic_scene();
  // Two lanes run the ego's way (y = 0 and 3.5), the oncoming one at y = 7.
  auto r = plan(s, "a car 20 m ahead in the lane next to the centre line");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.resolved.lane_edge, "inner");
  EXPECT_EQ(r.lane, "left");
  r = plan(s, "a car 20 m ahead in the fast lane");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "left");
  EXPECT_FALSE(r.resolved.speed_mps && *r.resolved.speed_mps > 12);  // "fast lane" names a lane, not a speed
  r = plan(s, "a car 10 m ahead in the slow lane");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "ego");
}

TEST(Planner, WithNoSpeedSaidItKeepsThePaceOfFasterTrafficBehind) {
  auto s = test_support::synthetic_scene();
  s.objects.pop_back();  // no truck ahead
  PlanRequest req;
  req.intent = parse_motion("a car 15 m ahead in my lane");
  req.type = "car";
  req.obstacles = scene_obstacles(s, {});
  Obstacle fast{"fast_car", {4.5, 1.9, 1.5}, {}, false};
  for (int i = 0; i < 51; ++i) fast.poses.push_back(Pose2{-5 + 1.4 * i, 0, 0});  // 14 m/s in the ego lane
  req.obstacles.push_back(fast);
  const auto r = plan_motion(s, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "ego");
  EXPECT_NEAR(r.speed_mps, 14, 0.5);
  EXPECT_FALSE(collides(r, req.obstacles, {4.5, 1.9, 1.5}));
  // A speed the user said stands: slow, somewhere the fast car does not catch it, or refused.
  req.intent = parse_motion("a car 15 m ahead in my lane driving slowly");
  const auto slow = plan_motion(s, req);
  if (slow.ok) {
    EXPECT_LT(slow.speed_mps, 6);
    EXPECT_FALSE(collides(slow, req.obstacles, {4.5, 1.9, 1.5}));
  }
}

// Blind layouts (tests/data/layouts): a T junction with slower traffic ahead, parking on the left.
TEST(Planner, ATurnBehindSlowerTrafficStartsAheadOfItAndParkingFindsItsSide) {
  const auto dir = std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts";
  const auto tee = chatsim::scene::load_scene(dir / "blind-tee");
  PlanRequest req;
  req.intent = parse_motion("a taxi 20 m ahead turning right at the t junction");
  req.type = "car";
  req.obstacles = scene_obstacles(tee, {});
  auto r = plan_motion(tee, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_LT(heading_change_deg(r.trajectory), -60);
  EXPECT_FALSE(collides(r, req.obstacles, req.size_lwh));
  // "in the parking lane" with no side said: the side the parking is on (the left here).
  const auto bend = chatsim::scene::load_scene(dir / "blind-rightbend");
  req.intent = parse_motion("a car parked in the parking lane");
  req.obstacles = scene_obstacles(bend, {});
  r = plan_motion(bend, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "parking_left");
}

// "The right lane" where the ego drives in the rightmost lane is that lane; "the on-ramp" is the
// lane that merges; a scene of many vehicles refuses a start off the lane asked for.
TEST(Planner, TheRightLaneTheRampAndStrictLanes) {
  const auto dir = std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts";
  const auto ramp = chatsim::scene::load_scene(dir / "blind-onramp");
  PlanRequest req;
  req.type = "car";  // no obstacles: the lane words alone decide
  req.intent = parse_motion("a car in the right lane 10 m ahead");
  auto r = plan_motion(ramp, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "east_right");
  EXPECT_TRUE(r.notes.empty()) << r.notes.front();  // the lane asked for, not a stand-in
  req.obstacles = scene_obstacles(ramp, {});
  req.intent = parse_motion("a car on the on-ramp");
  r = plan_motion(ramp, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "on_ramp");
  // The one-way layout's left lane: its recorded traffic runs into anything slow put near; the
  // second look goes further up that lane (beyond where that traffic gets to), and says so.
  const auto oneway = chatsim::scene::load_scene(dir / "blind-oneway");
  req.obstacles = scene_obstacles(oneway, {});
  req.intent = parse_motion("a car in the left lane driving slowly");
  req.strict = true;
  r = plan_motion(oneway, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.lane, "lane_left");
  EXPECT_GT(r.trajectory.front().x, 70.0);
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes.front().find("further"), std::string::npos) << r.notes.front();
  // Slow in the left lane 20 m ahead: the distance holds, so another lane, and said.
  req.intent = parse_motion("a car in the left lane 20 m ahead driving slowly");
  req.strict = false;
  r = plan_motion(oneway, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_NE(r.lane, "lane_left");
  EXPECT_FALSE(r.notes.empty());
  req.strict = true;
  EXPECT_FALSE(plan_motion(oneway, req).ok);
}
