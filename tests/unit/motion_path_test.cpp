// The path geometry the planner's early tests rest on: they skip simulating starts that cannot do
// what was asked, so each must never reject a start the full simulation would keep.
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "agents/motion/path.hpp"
#include "common/scene/lane_map.hpp"

using namespace chatsim;
using namespace chatsim::agents::motion;

namespace {

constexpr double kPi = std::numbers::pi;

// Straight along +x for `straight` metres, then a quarter circle of radius r to the left.
Path straight_then_left(double straight, double r) {
  Path p;
  for (double x = 0; x <= straight; x += 0.5) p.push({x, 0});
  for (double a = 0.02; a <= kPi / 2; a += 0.02) p.push({straight + r * std::sin(a), r - r * std::cos(a)});
  return p;
}

scene::Lane straight_lane(const std::string& id, double y, scene::TrafficDirection dir) {
  scene::Lane l;
  l.id = id;
  l.centerline = {{0, y, 0}, {200, y, 0}};
  l.direction = dir;
  return l;
}

std::vector<double> clip_times(double seconds) {
  std::vector<double> t;
  for (int i = 0; i <= int(seconds * 10); ++i) t.push_back(i * 0.1);
  return t;
}

}  // namespace

TEST(MotionPath, ArcWhereTurnedFindsTheBendAndNothingOnAStraight) {
  const Path bend = straight_then_left(40, 10);
  const double at60 = arc_where_turned(bend, 0, 60);
  // The quarter circle starts at 40 m; 60 degrees of it is 10.5 m of arc (the heading is taken
  // over 1.5 m, so it leads by up to 0.75 m).
  EXPECT_GT(at60, 40 + 10.47 - 1.0);
  EXPECT_LT(at60, 40 + 10.47 + 0.5);
  EXPECT_LT(arc_where_turned(bend, 0, 30), at60);
  Path line;
  for (double x = 0; x <= 100; x += 0.5) line.push({x, 0});
  EXPECT_TRUE(std::isinf(arc_where_turned(line, 0, 10)));
  EXPECT_TRUE(std::isinf(arc_where_turned(bend, 0, 120)));  // it turns 90 degrees, never 120
}

TEST(MotionPath, TrackedTurnOnlyHappensWhereArcWhereTurnedSaysItCan) {
  // The planner skips simulating a turn whose bend the free-flow profile cannot reach (with the
  // pursuit's look-ahead and 5 m to spare); wherever a simulated vehicle did turn 60 degrees,
  // that test must have let it through.
  const Path bend = straight_then_left(40, 12);
  const auto times = clip_times(8);
  int turns = 0, skipped = 0;
  for (double speed : {3.0, 4.0, 5.0, 6.0, 8.0, 12.0}) {
    const auto arc = arc_lengths_at(bend, speed, times);
    const auto poses = bicycle_track(bend, arc, times);
    const double turned = std::remainder(poses.back().yaw - poses.front().yaw, 2 * kPi) * 180 / kPi;
    double v_max = 0;
    for (size_t f = 0; f + 1 < arc.size(); ++f) v_max = std::max(v_max, (arc[f + 1] - arc[f]) / 0.1);
    const bool reachable = arc.back() + std::max(3.0, 0.9 * v_max) + 5.0 >= arc_where_turned(bend, arc.front(), 55);
    if (turned >= 60) {
      ++turns;
      EXPECT_TRUE(reachable) << speed << " m/s";
    }
    if (!reachable) ++skipped;
  }
  // Both sides of the test were exercised: some speeds turn in the clip, some are skipped.
  EXPECT_GT(turns, 0);
  EXPECT_GT(skipped, 0);
}

TEST(MotionPath, ArcLengthsSlowForABendAndNotOnAStraight) {
  const auto times = clip_times(10);
  Path line;
  for (double x = 0; x <= 300; x += 0.5) line.push({x, 0});
  const auto free = arc_lengths_at(line, 15, times);
  EXPECT_NEAR(free.back() - free.front(), 150, 1e-6);
  // A 10 m radius allows sqrt(3 * 10) = 5.5 m/s: somewhere on the bend the vehicle is that slow.
  const Path bend = straight_then_left(20, 10);
  const auto arc = arc_lengths_at(bend, 15, times);
  double slowest_on_bend = 1e9;
  for (size_t f = 0; f + 1 < arc.size(); ++f)
    if (arc[f] > 22 && arc[f] < 33) slowest_on_bend = std::min(slowest_on_bend, (arc[f + 1] - arc[f]) / 0.1);
  EXPECT_LT(slowest_on_bend, std::sqrt(30.0) + 0.3);
  EXPECT_GT(slowest_on_bend, std::sqrt(30.0) - 1.5);
}

TEST(MotionPath, MayHaveLaneBesideAnswersLikeTheLaneChangeItGuards) {
  using scene::TrafficDirection;
  const scene::LaneMap map({straight_lane("mine", 0, TrafficDirection::Forward),
                            straight_lane("left_same_way", 3.5, TrafficDirection::Forward),
                            straight_lane("right_oncoming", -3.5, TrafficDirection::Backward)});
  for (int sign : {1, -1}) {
    const bool may = may_have_lane_beside(map, 0, 50, 1, sign);
    const auto plan = lane_change_path(map, 0, 50, 1, sign, 100, 2, 15);
    EXPECT_EQ(may, !plan.target_lane.empty()) << "side " << sign;
  }
  EXPECT_TRUE(may_have_lane_beside(map, 0, 50, 1, 1));
  EXPECT_FALSE(may_have_lane_beside(map, 0, 50, 1, -1));  // the lane there runs the other way
}

TEST(MotionPath, PursuitStaysOnABendAtAnySpeed) {
  // Its steps are about 0.3 m of travel (20 to 100 ms): slow or fast, the tracked vehicle cuts the
  // bend by at most the metre its look-ahead allows, and ends each frame where the frame is.
  const Path bend = straight_then_left(20, 15);
  const auto times = clip_times(10);
  for (double speed : {1.5, 3.0, 6.0, 12.0}) {
    const auto arc = arc_lengths_at(bend, speed, times);
    const auto poses = bicycle_track(bend, arc, times);
    ASSERT_EQ(poses.size(), times.size());
    double worst = 0;
    for (size_t f = 0; f < poses.size() && arc[f] < bend.length() - 3; ++f) {  // past its end it runs on straight
      const auto& q = poses[f];
      double nearest = 1e9;
      for (const auto& p : bend.points) nearest = std::min(nearest, std::hypot(p.x() - q.x, p.y() - q.y));
      worst = std::max(worst, nearest);
    }
    EXPECT_LT(worst, 1.0) << speed << " m/s";
  }
}

TEST(MotionPath, AKinkWhereTwoStraightSegmentsMeetDoesNotSlowLikeABend) {
  // Two straight map segments meeting at 5 degrees (a lane shifting over by a metre or two), driven
  // at 22 m/s: a driver takes that kink within a second, as on a straight; a bend of the same
  // heading change squeezed into 2 m would allow about 12 m/s (bend_accel's hurried 6 m/s^2).
  const auto times = clip_times(6);
  const auto kinked = [](double degrees) {  // 60 m along +x, then 100 m turned by `degrees` at once
    Path p;
    for (double x = 0; x <= 60; x += 0.5) p.push({x, 0});
    const double a = degrees * kPi / 180;
    for (double d = 0.5; d <= 100; d += 0.5) p.push({60 + d * std::cos(a), d * std::sin(a)});
    return p;
  };
  const auto arc = arc_lengths_at(kinked(5), 22, times, 6.0);
  EXPECT_GT((arc.back() - arc.front()) / 6.0, 21.0);
  // A 15 degree turn is driven by its tightest 2 m, as before: the same kink three times as sharp.
  const auto slowed = arc_lengths_at(kinked(15), 22, times, 6.0);
  EXPECT_LT((slowed.back() - slowed.front()) / 6.0, 18.0);
}
