// What blind set v26 showed, on a crossroads the ego turns right at and a street by a school:
// commands in shorthand (numbered steps, "&", "LHS", "w/", yards), vehicles picked by waiting in a
// queue or by standing in the street the ego turns into, placements said by a relation the
// interpreter did not know ("tailgating", "opposite", "parked after"), a new vehicle made to do
// something ("have a cab drive ..."), "the first one" of those just removed, and street furniture
// that is no vehicle. Each test is a class of failure, not one of the set's cases.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using chatsim::testing::LayoutChat;
using chatsim::testing::removed_ids;
using nlohmann::json;

TEST(SaidInShorthand, ListsAbbreviationsAndUnitsAreRead) {
  LayoutChat street("blind-school");  // obj_1 the cyclist ahead, obj_8 the school bus
  EXPECT_EQ(removed_ids(street("a", "(a) remove the school bus (b) remove the cyclist")),
            (std::vector<std::string>{"obj_1", "obj_8"}));
  EXPECT_EQ(removed_ids(street("b", "- delete the cyclist\n- delete the school bus")),
            (std::vector<std::string>{"obj_1", "obj_8"}));
  // "Clear the RHS of parked cars": the side stays said (obj_2 stands in its driveway until it backs out).
  EXPECT_EQ(removed_ids(street("c", "clear the RHS of parked cars")),
            (std::vector<std::string>{"obj_11", "obj_2", "obj_3", "obj_4", "obj_5"}));
  const auto moved = street("d", "remove the cyclist & move the view 5 yards forward");
  EXPECT_EQ(removed_ids(moved), (std::vector<std::string>{"obj_1"}));
  EXPECT_NEAR(moved["view"]["translation_m"][0].get<double>(), 4.572, 1e-3);
  // "w/ its hazards on, ...": a leading "with" phrase belongs to the clause after it.
  const auto hazards = street("e", "w/ its hazards on, add a white van parked on the right")["added"];
  ASSERT_EQ(hazards.size(), 1u);
  // "a quarter to the left" after a camera clause is the camera's turn.
  EXPECT_NEAR(street("f", "raise the camera 1 m and turn it a quarter to the left")["view"]["yaw_deg"].get<double>(), 90,
              1e-6);
}

TEST(SaidInShorthand, WaitingInAQueueAndTheStreetTheEgoTurnsInto) {
  LayoutChat junction("blind-rightturn");  // obj_2, obj_3 wait on the cross street; obj_5, obj_6 park there
  EXPECT_EQ(removed_ids(junction("a", "remove every car waiting on the right")),
            (std::vector<std::string>{"obj_2", "obj_3"}));
  EXPECT_EQ(removed_ids(junction("b", "remove the cars parked in the road we turn into")),
            (std::vector<std::string>{"obj_5", "obj_6"}));
  const auto parked = junction("c", "add a van parked in the street we are turning into")["added"];
  ASSERT_EQ(parked.size(), 1u);
  EXPECT_NEAR(parked[0]["trajectory"][0]["x"].get<double>(), 35.25, 0.5);  // the cross street's parking lane
  // Traffic lights are no traffic: nothing is removed, and the refusal says why.
  const auto lights = junction("d", "delete the traffic lights");
  EXPECT_TRUE(removed_ids(lights).empty());
  EXPECT_FALSE(lights["unresolved"].empty());
}

TEST(SaidInShorthand, RelationsCausativesAndTheOnesJustRemoved) {
  LayoutChat street("blind-school");  // obj_13 an orange car behind the ego; obj_8 the bus at x = 80 on the left
  const auto tail = street("a", "add a grey car tailgating the orange car")["added"];
  ASSERT_EQ(tail.size(), 1u);
  EXPECT_LT(tail[0]["trajectory"][0]["x"].get<double>(), -14);  // behind the orange car at x = -10
  EXPECT_LT(tail[0]["color_rgb"][0].get<int>(), 200);          // grey, not the anchor's orange
  const auto across = street("b", "add a car parked across the road from the school bus")["added"];
  ASSERT_EQ(across.size(), 1u);
  EXPECT_NEAR(across[0]["trajectory"][0]["x"].get<double>(), 80, 8);
  EXPECT_LT(across[0]["trajectory"][0]["y"].get<double>(), 1);  // the bus is on the left: this is right of it
  const auto cab = street("c", "remove the cyclist and have a taxi drive ahead of us in its place")["added"];
  ASSERT_EQ(cab.size(), 1u);
  LayoutChat junction("blind-rightturn");
  const auto first = junction("d", "remove the cars waiting on the right, then park a police car where the first one was");
  ASSERT_EQ(first["added"].size(), 1u);
  EXPECT_NEAR(first["added"][0]["trajectory"][0]["y"].get<double>(), -12, 2);  // obj_2, the first removed
}

TEST(SaidInShorthand, ParkedAfterIsPastItAsTheEgoSeesIt) {
  LayoutChat street("blind-zebra");
  const auto after = street("a", "add a taxi parked on the left after the green car")["added"];
  ASSERT_EQ(after.size(), 1u);
  const auto before = street("b", "add a taxi parked on the left before the green car")["added"];
  ASSERT_EQ(before.size(), 1u);
  EXPECT_GT(after[0]["trajectory"][0]["x"].get<double>(), before[0]["trajectory"][0]["x"].get<double>());
}
