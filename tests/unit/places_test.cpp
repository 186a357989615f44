// Places along the road a user names: past or before a junction, in a car park, on a hard shoulder
// the map draws, the lane that ends; and views moved to a lane or turned by a bare number. Each
// test is a class of failure blind set v19 showed, not one of its cases.
#include <gtest/gtest.h>

#include "agents/deletion/deletion.hpp"
#include "agents/language/lane_names.hpp"
#include "agents/language/text.hpp"
#include "agents/motion/motion_intent.hpp"
#include "common/scene/lane_map.hpp"
#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using chatsim::testing::LayoutChat;
using chatsim::testing::straight_lane;

namespace {

std::vector<std::string> removed(const nlohmann::json& state) {
  return state["removed"].get<std::vector<std::string>>();
}

}  // namespace

TEST(Places, TheJunctionAheadSpansTheLanesCrossingTheEgosLane) {
  // East along y=0; a two-lane street crossing at x=43 and x=47; nothing crosses behind.
  const scene::LaneMap map({straight_lane("main", -60, 0, 200, 0), straight_lane("cross_a", 43, -80, 43, 80),
                            straight_lane("cross_b", 47, 80, 47, -80)});
  const auto span = map.junction_ahead({0, 0}, 0.0);
  ASSERT_TRUE(span);
  EXPECT_NEAR(span->from, 43, 0.5);
  EXPECT_NEAR(span->to, 47, 0.5);
  EXPECT_FALSE(map.junction_ahead({60, 0}, 0.0));  // past it, none ahead
  EXPECT_FALSE(scene::LaneMap({straight_lane("main", -60, 0, 200, 0)}).junction_ahead({0, 0}, 0.0));
}

TEST(Places, ALaneDrawnTaperingIntoItsNeighbourMergesAndAContinuationDoesNot) {
  auto drop = straight_lane("left_ends", -60, 3.5, 80, 3.5);
  drop.centerline.push_back({95, 1.75, 0});
  drop.centerline.push_back({110, 0, 0});
  const scene::LaneMap map({straight_lane("right", -60, 0, 200, 0), drop, straight_lane("next", 200, 0, 300, 0)});
  EXPECT_TRUE(map.merges(1));
  EXPECT_FALSE(map.merges(0));  // "right" ends where "next" starts: one lane going on
}

TEST(Places, WhereAlongTheRoadIsAPlaceNotTheCrossStreetsLane) {
  const auto d = agents::deletion::parse_deletion("remove the parked cars past the junction");
  ASSERT_EQ(d.targets.size(), 1u);
  EXPECT_EQ(d.targets[0].junction, "after");
  EXPECT_FALSE(d.targets[0].lane);
  const auto m = agents::motion::parse_motion("add a van parked 20 m before the crossing");
  EXPECT_EQ(m.junction, "before");
  EXPECT_EQ(m.distance_m, 20.0);
  EXPECT_NE(m.lane, "cross");
  EXPECT_EQ(agents::language::find_lane_name(agents::text::words("the car in the parking lot"))->use, "car_park");
}

TEST(Places, JunctionsCarParksShouldersAndLaneDropsSelectWhatStandsThere) {
  LayoutChat grid("blind-onewaygrid");
  EXPECT_EQ(removed(grid("a", "remove the parked cars past the junction")),
            (std::vector<std::string>{"obj_4", "obj_6"}));
  EXPECT_EQ(removed(grid("b", "remove the parked cars before the junction")),
            (std::vector<std::string>{"obj_5", "obj_3"}));
  LayoutChat drop("blind-lanedrop");
  EXPECT_EQ(removed(drop("a", "remove the cars in the car park")).size(), 3u);  // the one pulling out too
  EXPECT_EQ(removed(drop("b", "remove the car leaving the car park")), (std::vector<std::string>{"obj_3"}));
  EXPECT_EQ(removed(drop("c", "delete the car in the lane that ends")), (std::vector<std::string>{"obj_5"}));
  LayoutChat motorway("blind-motorway");
  // A car stopped on the hard shoulder beside a police car: "the car" is the plain one.
  EXPECT_EQ(removed(motorway("a", "remove the stalled car on the hard shoulder")), (std::vector<std::string>{"obj_3"}));
  EXPECT_EQ(removed(motorway("b", "remove the police car and the yellow car as well")).size(), 2u);
}

TEST(Places, AddedVehiclesStandWhereThePlaceIs) {
  LayoutChat drop("blind-lanedrop");
  const auto parked = drop("a", "add a car parked in the car park")["added"][0];
  EXPECT_EQ(parked["intent"]["lane"], "car_park_bays");  // its bays, not its aisle
  const auto filled = drop("b", "fill the car park")["added"];
  EXPECT_GE(filled.size(), 3u);
  for (const auto& v : filled) EXPECT_EQ(v["intent"]["action"], "static");
  LayoutChat grid("blind-onewaygrid");
  const auto past = grid("a", "add a van parked on the right after the crossing")["added"][0]["trajectory"][0];
  EXPECT_GT(past["x"].get<double>(), 48.0);  // beyond the cross street (x 43-47)
}

TEST(Places, AViewMovesToALaneBesideTheRoadOrSaysThereIsNone) {
  LayoutChat grid("blind-onewaygrid");
  EXPECT_EQ(grid("a", "look from the right lane")["view"]["translation_m"][1], -3.5);
  LayoutChat drop("blind-lanedrop");
  // No lane of the ego's way to its right (a car park's aisle 20 m off is none): said, and the
  // conversation goes on.
  auto state = drop("b", "move the view to the right lane");
  ASSERT_EQ(state["unresolved"].size(), 1u);
  EXPECT_EQ(state["view"]["translation_m"][1], 0.0);
  state = drop("b", "raise the camera by one and a half metres and rotate left by 45");
  EXPECT_EQ(state["view"]["translation_m"][2], 1.5);
  EXPECT_EQ(state["view"]["yaw_deg"], 45.0);
}

TEST(Places, ABareNumberAfterATurningVerbIsAnAngle) {
  auto w = agents::text::words("raise it by one and a half metres and rotate left by 45");
  agents::text::bare_turns_to_degrees(w);
  EXPECT_EQ(agents::text::join(w), "raise it by one and a half meters and rotate left by 45 degrees");
  w = agents::text::words("pan 20 to the right then move 3 m forward");
  agents::text::bare_turns_to_degrees(w);
  EXPECT_EQ(agents::text::join(w), "pan 20 degrees to the right then move 3 m forward");
}

TEST(Places, TrafficMadeHeavyIsABusyRoadOnTheRoadNamed) {
  LayoutChat fork("blind-fork");
  const auto added = fork("a", "make the traffic heavy on the branch road")["added"];
  ASSERT_GE(added.size(), 3u);
  for (const auto& v : added) EXPECT_EQ(v["intent"]["lane"], "north_branch");
}
