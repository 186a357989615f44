// What blind set v24 showed, on a minor road meeting a main road and a US arterial with a centre
// turn lane, a strip mall and a gas station: commands written as test specs, distance bounds,
// pickups labelled as cars, car parks the map does not name, "the main road", traffic coming from
// one side, "ahead" in a lane off to the side. Each test is a class of failure, not one case.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "agents/manager/spec_fields.hpp"
#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using chatsim::testing::LayoutChat;
using chatsim::testing::removed_ids;
using nlohmann::json;

namespace {

const json& start(const json& added) { return added["trajectory"][0]; }

}  // namespace

TEST(SpecAndPlace, ATestSpecIsOneInstructionOfItsFields) {
  const auto s = agents::manager::spec_as_sentence(
      "Scenario: lead vehicle. Actor: grey Volvo XC90. Start: 25 m ahead in ego lane. Speed: 20 km/h.");
  ASSERT_TRUE(s);
  EXPECT_NE(s->find("add a grey volvo xc90"), std::string::npos) << *s;
  EXPECT_NE(s->find("25 m ahead in my lane"), std::string::npos) << *s;
  EXPECT_NE(s->find("at 20 km/h"), std::string::npos) << *s;
  EXPECT_NE(s->find("same way as me"), std::string::npos) << *s;  // a lead vehicle goes the ego's way
  EXPECT_EQ(agents::manager::spec_as_sentence("Target: all vehicles on the main road. Action: delete."),
            "remove all vehicles on the main road");
  // A colon in a sentence is a title, not a spec.
  EXPECT_FALSE(agents::manager::spec_as_sentence("Simulate a breakdown: a van stopped in my lane, cones behind it"));
  LayoutChat road("blind-giveway");
  const auto state = road("a", "Spawn NPC: type=taxi, colour=yellow, position=ego lane 20 m ahead, speed=15 km/h");
  ASSERT_EQ(state["added"].size(), 1u);
  EXPECT_TRUE(state["unresolved"].empty()) << state["unresolved"];
  EXPECT_EQ(state["added"][0]["type"], "taxi");
  EXPECT_NEAR(start(state["added"][0])["x"].get<double>(), 20, 5);
}

TEST(SpecAndPlace, DistanceBoundsSelectByHowFarFromTheEgo) {
  LayoutChat road("blind-giveway");  // parked: obj_12 10.8 m, obj_1 15.3 m, obj_2 24.2 m, the bus 69 m
  EXPECT_EQ(removed_ids(road("a", "remove all parked vehicles within 20 metres of me")),
            (std::vector<std::string>{"obj_1", "obj_12"}));
  EXPECT_EQ(removed_ids(road("b", "remove every parked vehicle more than 20 m away")),
            (std::vector<std::string>{"obj_2", "obj_6"}));
  EXPECT_EQ(removed_ids(road("c", "delete the parked cars closer than 60 feet")),
            (std::vector<std::string>{"obj_1", "obj_12"}));
}

TEST(SpecAndPlace, APickupIsALongLowCarOrAShortTruck) {
  LayoutChat arterial("blind-twltl");  // obj_1: a 5.4 m pickup labelled a car; obj_13: a 7.5 m lorry
  EXPECT_EQ(removed_ids(arterial("a", "remove the pickup")), (std::vector<std::string>{"obj_1"}));
  EXPECT_EQ(removed_ids(arterial("b", "remove the truck in the parking lot")), (std::vector<std::string>{"obj_13"}));
}

TEST(SpecAndPlace, ACarParkIsFoundByItsShapeWhenNoLaneNamesIt) {
  LayoutChat arterial("blind-twltl");  // the strip mall's bays along a two-way aisle; the road has none
  EXPECT_EQ(removed_ids(arterial("a", "remove all the cars in the parking lot")),
            (std::vector<std::string>{"obj_10", "obj_12", "obj_13", "obj_6"}));
  const auto added = arterial("b", "add three cars to the parking lot")["added"];
  ASSERT_EQ(added.size(), 3u);
  for (const auto& a : added) EXPECT_LT(start(a)["y"].get<double>(), -20) << a;  // in the lot, south of the road
}

TEST(SpecAndPlace, TheMainRoadIsTheBiggerRoadTheEgosJoins) {
  LayoutChat road("blind-giveway");  // the ego's two-lane minor road meets a four-lane main road
  const auto gone = removed_ids(road("a", "remove all vehicles on the main road"));
  EXPECT_EQ(gone, (std::vector<std::string>{"obj_11", "obj_4", "obj_5", "obj_7", "obj_8"}));
  // Across the junction: past it, where the bus stands at its stop.
  EXPECT_EQ(removed_ids(road("b", "get rid of the bus at the stop across the junction")),
            (std::vector<std::string>{"obj_6"}));
}

TEST(SpecAndPlace, TrafficFromOneSideComesAlongARoadAcrossTheEgos) {
  LayoutChat road("blind-giveway");
  const auto added = road("a", "add a red fire engine coming down the main road from the right")["added"];
  ASSERT_EQ(added.size(), 1u);
  const auto& t = added[0]["trajectory"];
  EXPECT_GT(start(added[0])["x"].get<double>(), 40);  // on the main road ahead
  EXPECT_LT(start(added[0])["y"].get<double>(), 0);   // on the right
  EXPECT_GT(t[t.size() - 1]["y"].get<double>(), start(added[0])["y"].get<double>() + 20);  // coming across
}

TEST(SpecAndPlace, AheadInALaneToTheSideIsInFront) {
  LayoutChat arterial("blind-twltl");  // the centre turn lane is 7 m to the ego's left
  const auto added = arterial("a", "add a black Ford waiting in the center turn lane ahead")["added"];
  ASSERT_EQ(added.size(), 1u);
  const double x = start(added[0])["x"].get<double>(), y = start(added[0])["y"].get<double>();
  EXPECT_LE(std::abs(std::atan2(y, x)) * 180 / std::numbers::pi, 25) << x << ", " << y;
}

TEST(SpecAndPlace, ACarAheadOnARoadThatEndsAtATGoesRoundTheCorner) {
  LayoutChat road("blind-giveway");  // the ego's lane ends 44 m ahead at a four-lane main road
  const auto added = road("a", "remove the bicycle and add a red car 20 m ahead")["added"];
  ASSERT_EQ(added.size(), 1u);
  const auto& t = added[0]["trajectory"];
  EXPECT_LT(t[t.size() - 1]["y"].get<double>(), -10) << added[0]["intent"];  // turned onto the main road
  EXPECT_EQ(added[0]["intent"]["action"], "turn_right");
  // Where the road goes on, it goes straight on.
  LayoutChat dev("blind-avenue");
  const auto straight = dev("a", "add a red car 20 m ahead")["added"];
  ASSERT_EQ(straight.size(), 1u);
  EXPECT_EQ(straight[0]["intent"]["action"], "straight");
}

TEST(SpecAndPlace, PullingOutOfASideLaneWaitsForAGapAndLeavesFromItsMouth) {
  LayoutChat arterial("blind-twltl");  // the mall driveway meets a busy arterial
  const auto state = arterial("a", "add a car pulling out of the mall driveway");
  ASSERT_EQ(state["added"].size(), 1u);
  EXPECT_EQ(state["added"][0]["intent"]["lane"], "mall_driveway");
  const auto notes = state["notes"].dump();
  EXPECT_NE(notes.find("waits"), std::string::npos) << notes;
  // A cross street that runs on across the road: its lane toward the road, not beyond it.
  LayoutChat cross("blind-crossroads");
  const auto out = cross("a", "add a car pulling out of the side street on the right")["added"];
  ASSERT_EQ(out.size(), 1u);
  // On the right, on the cross street's lane toward the road (not on the ego's road).
  EXPECT_LT(start(out[0])["y"].get<double>(), -2) << out[0]["intent"];
  EXPECT_EQ(out[0]["intent"]["lane"].get<std::string>().rfind("north", 0), 0u) << out[0]["intent"];
  // The one standing at a driveway's mouth, waiting to leave, is the one meant.
  EXPECT_EQ(removed_ids(arterial("b", "delete the car waiting to leave the gas station")),
            (std::vector<std::string>{"obj_8"}));
}
