// What blind set v27 showed, on a mountain hairpin and an airport forecourt: vehicles picked by
// comparison ("the slower of the two"), by count ("two of the taxis"), by their place in a queue,
// taxis the scene labels only as yellow cars, a relative clause that negates; rounds said as
// "the same again" or "a green one instead"; a goal ("I need the forecourt empty"); lanes named
// by a hyphenated word; a colour taken from another vehicle. Each test is a class, not a case.
#include <gtest/gtest.h>

#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using chatsim::testing::LayoutChat;
using chatsim::testing::removed_ids;
using nlohmann::json;

TEST(SaidByComparison, ComparativesCountsQueuesAndTaxis) {
  // obj_1-3 yellow cars queueing at the kerb (x = 20, 26, 32), obj_11 another at 95; obj_6 a grey
  // car at 6 m/s and obj_7 a blue one at 4 m/s ahead in the through lanes.
  LayoutChat forecourt("blind-dropoff");
  EXPECT_EQ(removed_ids(forecourt("a", "delete the faster of the two cars ahead of us in the through lanes")),
            (std::vector<std::string>{"obj_6"}));
  EXPECT_EQ(removed_ids(forecourt("b", "remove three of the taxis")), (std::vector<std::string>{"obj_1", "obj_2", "obj_3"}));
  EXPECT_EQ(removed_ids(forecourt("c", "remove the cab at the head of the line")), (std::vector<std::string>{"obj_3"}));
  EXPECT_EQ(removed_ids(forecourt("d", "remove the cab at the end of the queue")), (std::vector<std::string>{"obj_1"}));
  EXPECT_EQ(removed_ids(forecourt("e", "delete all vehicles that are not taxis")),
            (std::vector<std::string>{"obj_4", "obj_5", "obj_6", "obj_7", "obj_8", "obj_9"}));
}

TEST(SaidByComparison, SameAgainInsteadGoalsAndHyphenatedLanes) {
  LayoutChat forecourt("blind-dropoff");
  forecourt("a", "delete the red car");
  EXPECT_EQ(removed_ids(forecourt("a", "do the same for the bus")), (std::vector<std::string>{"obj_8", "obj_9"}));
  forecourt("b", "add a blue van parked in the drop-off lane");
  const auto again = forecourt("b", "same again but black")["added"];
  ASSERT_EQ(again.size(), 2u);
  EXPECT_LT(again[1]["color_rgb"][2].get<int>(), 60);  // black, not blue
  forecourt("c", "add a red car in the left through lane");
  const auto instead = forecourt("c", "maybe a yellow one instead")["added"];
  ASSERT_EQ(instead.size(), 1u);
  EXPECT_GT(instead[0]["color_rgb"][1].get<int>(), 150);  // yellow
  EXPECT_EQ(removed_ids(forecourt("d", "I want the drop-off lane empty")),
            (std::vector<std::string>{"obj_1", "obj_11", "obj_2", "obj_3", "obj_4", "obj_5"}));
  // A lane named by a word the map does not have selects nothing, not everything.
  const auto none = forecourt("e", "clear the pick-up lane");
  EXPECT_TRUE(removed_ids(none).empty());
  EXPECT_FALSE(none["unresolved"].empty());
}

TEST(SaidByComparison, AColourTakenFromAnotherVehicleAndAMoodTitle) {
  LayoutChat mountain("blind-hairpin");  // obj_2 a white coach in the lay-by, obj_5 a yellow truck coming down
  mountain("a", "add a car parked in the lay-by");
  const auto same = mountain("a", "paint it the same colour as the truck")["added"];
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0]["category"], "vehicle.car");                                       // still a car
  EXPECT_GT(same[0]["color_rgb"][0].get<int>(), 180);                                  // yellow
  EXPECT_LT(same[0]["color_rgb"][2].get<int>(), 120);
  // "Quiet evening: ..." names a mood the detail makes: only the detail is added.
  EXPECT_EQ(mountain("b", "quiet evening: one car parked in the lay-by")["added"].size(), 1u);
}
