// What blind set v25 showed, on a high street with angled parking and a motorway merge: requests
// said indirectly (a hypothetical, a negation, a description of the scene, a non-native "please
// to"), vehicles picked by size or by standing in a lane, the ego as the subject ("the truck I'm
// merging behind"), a multiple of a distance, a lane change named by the kerb, and the gap kept
// to a moving vehicle. Each test is a class of failure, not one of the set's cases.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using chatsim::testing::LayoutChat;
using chatsim::testing::removed_ids;
using nlohmann::json;

TEST(SaidIndirectly, HypotheticalsNegationsAndDescriptionsSayWhatToDo) {
  LayoutChat street("blind-angled");  // obj_9: a white van double-parked in the ego's lane
  EXPECT_EQ(removed_ids(street("a", "what if the van that's double parked wasn't there?")),
            (std::vector<std::string>{"obj_9"}));
  // What is not to be touched is an exception to what follows "but".
  EXPECT_EQ(removed_ids(street("b", "don't touch the trucks, but get rid of every vehicle parked on the left")),
            (std::vector<std::string>{"obj_6", "obj_7", "obj_8"}));
  // A clause saying how a vehicle there is asks for nothing; "it" after it is that vehicle.
  const auto tow = street("c", "the white van has broken down and a tow truck is parked behind it")["added"];
  ASSERT_EQ(tow.size(), 1u);
  EXPECT_EQ(tow[0]["type"], "truck");
  EXPECT_NEAR(tow[0]["trajectory"][0]["x"].get<double>(), 47, 3);  // behind the van at x = 55
  EXPECT_EQ(removed_ids(street("d", "please to remove the car which is reversing out")),
            (std::vector<std::string>{"obj_10"}));
  // "Everything coming the other way" is every vehicle doing that, not every vehicle.
  EXPECT_EQ(removed_ids(street("e", "clear everything coming the other way")),
            (std::vector<std::string>{"obj_11", "obj_12", "obj_14"}));
}

TEST(SaidIndirectly, VehiclesArePickedBySizeByStandingInALaneAndFromTheEgosPlace) {
  LayoutChat street("blind-angled");
  EXPECT_EQ(removed_ids(street("a", "remove the largest vehicle parked on the left")),
            (std::vector<std::string>{"obj_15"}));
  EXPECT_EQ(removed_ids(street("b", "remove the van that's double parked")), (std::vector<std::string>{"obj_9"}));
  LayoutChat motorway("blind-merge");  // the ego on the on-ramp, a truck ahead in the lane it joins
  EXPECT_EQ(removed_ids(motorway("a", "remove the truck I'm merging behind")), (std::vector<std::string>{"obj_1"}));
}

TEST(SaidIndirectly, AFactorOfTheDistanceAKerbLaneAndTheGapToAMovingVehicle) {
  LayoutChat street("blind-angled");
  street("a", "add a red car 15 m ahead");
  const auto far = street("a", "make it twice as far away")["added"];
  ASSERT_EQ(far.size(), 1u);
  EXPECT_NEAR(far[0]["trajectory"][0]["x"].get<double>(), 30, 4);
  LayoutChat motorway("blind-merge");
  motorway("b", "add a black Audi in the middle lane");
  const auto moved = motorway("b", "make it change into the kerb lane")["added"];
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved[0]["intent"]["action"], "lane_change_right");  // the kerb is on the right here
  // Ahead of a truck doing 20 m/s: a second's headway, not 2 m.
  const auto ahead = motorway("c", "add a car ahead of the blue truck")["added"];
  ASSERT_EQ(ahead.size(), 1u);
  const auto& start = ahead[0]["trajectory"][0];
  EXPECT_GT(std::hypot(start["x"].get<double>() - 10, start["y"].get<double>()), 25);  // the truck starts at (10, 0)
}
