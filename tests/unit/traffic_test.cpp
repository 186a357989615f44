// Traffic on lane layouts unlike the dev one (tests/data/layouts): where recorded vehicles
// stand in lane words, side streets met at T junctions, car following and overtaking, and the
// motion words that hang on other phrases.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "agents/deletion/lane_relation.hpp"
#include "agents/motion/car_following.hpp"
#include "agents/motion/planner.hpp"
#include "common/scene/scene.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim;
using namespace chatsim::agents;

namespace {

scene::Scene layout(const std::string& name) {
  return scene::load_scene(std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts" / name);
}

deletion::LaneRelation relation_of(const scene::Scene& s, const std::string& id) {
  return deletion::lane_relation(s, s.object(id)->track.front().center.head<2>());
}

motion::PlanResult plan(const scene::Scene& s, const std::string& instruction) {
  motion::PlanRequest req;
  req.intent = motion::parse_motion(instruction);
  req.obstacles = motion::scene_obstacles(s, {});
  return motion::plan_motion(s, req);
}

double mean_speed(const motion::PlanResult& r) {
  const auto& a = r.trajectory.front();
  const auto& b = r.trajectory.back();
  return std::hypot(b.x - a.x, b.y - a.y) / r.t_s.back();
}

}  // namespace

TEST(Traffic, RecordedVehiclesAreNamedByTheirLane) {
  const auto s = layout("blind-divided");  // ego in the right lane of three, crossroads at 50 m
  EXPECT_TRUE(relation_of(s, "obj_1").middle);
  EXPECT_TRUE(relation_of(s, "obj_2").left);
  const auto truck = relation_of(s, "obj_3");
  EXPECT_TRUE(truck.ego && truck.right && !truck.left);
  EXPECT_TRUE(relation_of(s, "obj_4").parking);
  EXPECT_TRUE(relation_of(s, "obj_6").oncoming);
  EXPECT_TRUE(relation_of(s, "obj_8").cross);
  // On a road bending left, the oncoming car in the bend is still oncoming.
  EXPECT_TRUE(relation_of(layout("blind-curve"), "obj_3").oncoming);
}

TEST(Traffic, SideStreetsThatStartAtTheKerbAreJunctions) {
  const auto s = layout("blind-oneway");  // side streets right at x=35 and left at x=95
  int middle = -1, side = -1;
  for (size_t i = 0; i < s.lanes.lanes().size(); ++i) {
    if (s.lanes.lanes()[i].id == "lane_middle") middle = int(i);
    if (s.lanes.lanes()[i].id == "side_right_south") side = int(i);
  }
  ASSERT_GE(middle, 0);
  ASSERT_GE(side, 0);
  bool found = false;
  for (const auto& j : s.lanes.junctions(middle, 12.0))
    if (j.other == side) {
      found = true;
      EXPECT_NEAR(j.s_self, 60 + 33.25, 0.5);  // the middle lane starts at x = -60
    }
  EXPECT_TRUE(found);
  EXPECT_TRUE(s.lanes.crossings(middle).empty());  // nothing crosses: the old turn search found nothing
  const auto r = plan(s, "a car 10 m ahead that turns right");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_LT(std::remainder(r.trajectory.back().yaw - r.trajectory.front().yaw, 2 * M_PI), -1.0);
}

TEST(Traffic, CarFollowingNeverClosesOnASlowerLeader) {
  motion::Path path;
  for (int i = 0; i <= 400; ++i) path.push({0.5 * i, 0});
  std::vector<double> times, free_arc;
  for (int f = 0; f < 100; ++f) {
    times.push_back(0.1 * f);
    free_arc.push_back(14.0 * 0.1 * f);
  }
  std::vector<std::optional<motion::Pose2>> leader;
  for (int f = 0; f < 100; ++f) leader.emplace_back(motion::Pose2{20 + 5.0 * 0.1 * f, 0, 0});
  const Eigen::Vector3d size(4.5, 1.9, 1.5);
  const auto arc = motion::follow_leaders(path, free_arc, times, size, {{size, &leader}});
  for (int f = 0; f < 100; ++f) EXPECT_GT(leader[size_t(f)]->x - arc[size_t(f)] - size.x(), 0.5) << "frame " << f;
  EXPECT_NEAR((arc.back() - arc[50]) / (times.back() - times[50]), 5.0, 1.0);  // it settles at the leader's speed
  // A leader faster than we want to go is no constraint, however close it starts.
  std::vector<std::optional<motion::Pose2>> fast_leader;
  std::vector<double> slow_free;
  for (int f = 0; f < 100; ++f) {
    fast_leader.emplace_back(motion::Pose2{6 + 12.0 * 0.1 * f, 0, 0});
    slow_free.push_back(8.0 * 0.1 * f);
  }
  const auto unhindered = motion::follow_leaders(path, slow_free, times, size, {{size, &fast_leader}});
  EXPECT_NEAR(unhindered.back(), slow_free.back(), 0.5);
}

TEST(Traffic, AddedVehiclesFollowOrOvertakeInsteadOfDrivingThrough) {
  const auto s = layout("blind-curve");  // a grey car 30 m ahead in the ego lane at 7 m/s
  auto r = plan(s, "a car 15 m ahead");
  ASSERT_TRUE(r.ok) << r.reason;
  for (size_t f = 0; f < r.trajectory.size(); ++f) {
    const auto grey = s.object("obj_2")->at(int(f));
    EXPECT_FALSE(motion::boxes_overlap(r.trajectory[f], {4.5, 1.9, 1.5}, {grey->center.x(), grey->center.y(), grey->yaw},
                                       s.object("obj_2")->size_lwh))
        << "frame " << f;
  }
  // A truck 40 m ahead in the ego lane at 7 m/s, the lane to the left free: asked to go fast,
  // it passes instead of trailing.
  const auto synthetic = test_support::synthetic_scene();
  r = plan(synthetic, "a fast car 15 m ahead");
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.resolved.action, "lane_change_left");
  EXPECT_GT(mean_speed(r), 9.0);  // the truck's 7 m/s, had it trailed; the curve of the change costs some
  const auto* truck = synthetic.object("moving_truck");
  for (size_t f = 0; f < r.trajectory.size(); ++f) {
    const auto t = truck->at(int(f));
    EXPECT_FALSE(motion::boxes_overlap(r.trajectory[f], {4.5, 1.9, 1.5}, {t->center.x(), t->center.y(), t->yaw}, truck->size_lwh))
        << "frame " << f;
  }
}

TEST(Traffic, MotionWordsThatHangOnOtherPhrases) {
  auto m = motion::parse_motion("move it 10 metres further away");
  EXPECT_FALSE(m.distance_m);
  EXPECT_EQ(m.distance_change_m.value_or(0), 10);
  m = motion::parse_motion("add a green van in its place");
  ASSERT_TRUE(m.relative);
  EXPECT_EQ(m.relative->region, "at");
  EXPECT_EQ(m.relative->to, "removed");
  m = motion::parse_motion("a tesla changing into the right lane ahead of me");
  EXPECT_EQ(m.action, "lane_change_right");
  EXPECT_FALSE(m.lane);  // the right lane is where it goes, not where it starts
  m = motion::parse_motion("a car on the wrong side of the road");
  EXPECT_TRUE(m.wrong_way.value_or(false));
  EXPECT_NE(m.lane.value_or(""), "parking");
  EXPECT_FALSE(motion::parse_motion("add a car -5 m ahead").problems.empty());
  EXPECT_FALSE(motion::parse_motion("add a car 2 km ahead").problems.empty());
  EXPECT_FALSE(motion::parse_motion("a car at 900 km/h").problems.empty());
  EXPECT_NEAR(motion::parse_motion("a coach at 50 kilometres per hour").speed_mps.value_or(0), 50 / 3.6, 1e-9);
}

TEST(Traffic, ALaneUsedBothWaysMeetsTheRoadAtEitherEnd) {
  const auto s = layout("blind-twltl");  // the mall driveway is drawn from the road outward, used both ways
  const int driveway = s.lanes.find("mall_driveway"), kerb = s.lanes.find("east_kerb");
  ASSERT_GE(driveway, 0);
  ASSERT_GE(kerb, 0);
  bool meets_at_mouth = false;  // driving out of it (toward its start), its travel ends at the road
  for (const auto& j : s.lanes.junctions(driveway, 12.0))
    meets_at_mouth = meets_at_mouth || (j.other == kerb && j.s_self < 0.5);
  EXPECT_TRUE(meets_at_mouth);
}
