// What blind set v23 showed, on layouts unlike earlier ones in the traffic the ego is in (stopped in a
// queue; creeping along a car park aisle): rounds that go on from the last or correct it, vehicles
// picked by what they do at some time, places said by a model's name, a bay, "past" a vehicle, the
// far end or the junction. Each test is a class of failure, not one of the set's cases.
#include <cmath>

#include <gtest/gtest.h>

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using chatsim::testing::LayoutChat;
using nlohmann::json;

namespace {

std::vector<std::string> removed(const json& state) { return state["removed"].get<std::vector<std::string>>(); }

double start_x(const json& added) { return added["trajectory"][0]["x"].get<double>(); }
double start_y(const json& added) { return added["trajectory"][0]["y"].get<double>(); }

}  // namespace

TEST(TrafficState, ARoundGoesOnFromTheLastDeletionOrReplacesIt) {
  LayoutChat park("blind-carpark");
  park("a", "delete the red cars");
  EXPECT_EQ(removed(park("a", "and the yellow one")).size(), 3u);  // no noun of its own: still a deletion
  // "the next one along": the same words again pick the next nearest.
  park("b", "delete the nearest parked car on my right");
  const auto two = removed(park("b", "and the next one along"));
  EXPECT_EQ(two, (std::vector<std::string>{"obj_1", "obj_2"}));
  // "no, ... instead" undoes the round it corrects before it runs.
  park("c", "delete the delivery truck");
  const auto state = park("c", "no, delete the motorbike instead");
  EXPECT_EQ(removed(state), (std::vector<std::string>{"obj_11"}));
  // Without "instead" a second deletion adds to the first.
  park("d", "delete the delivery truck");
  EXPECT_EQ(removed(park("d", "no wait, delete the motorbike too")).size(), 2u);
}

TEST(TrafficState, VehiclesArePickedByWhatTheyDoAtSomeTimeAndWhereTheyStand) {
  LayoutChat park("blind-carpark");
  // It stands in its bay for most of the clip and backs out near its end; the car behind moves all along.
  EXPECT_EQ(removed(park("a", "remove the car that's backing out")), (std::vector<std::string>{"obj_4"}));
  // A row of bays holds what is parked in it, not the car driving past it.
  const auto row = removed(park("b", "clear the left row of bays"));
  EXPECT_EQ(row.size(), 5u);
  EXPECT_EQ(std::count(row.begin(), row.end(), "obj_7"), 0);
}

TEST(TrafficState, WhatCannotBeAddedIsRefusedWholeAndAQualifyingNounIsNot) {
  LayoutChat park("blind-carpark");
  const auto walker = park("a", "add a pedestrian pushing a trolley");
  EXPECT_TRUE(walker["added"].empty());
  ASSERT_EQ(walker["unresolved"].size(), 1u);
  EXPECT_NE(walker["unresolved"][0]["reason"].get<std::string>().find("pedestrian"), std::string::npos);
  const auto trailer = park("b", "add a horse box trailer parked on the right");
  EXPECT_EQ(trailer["added"].size(), 1u);
}

TEST(TrafficState, AModelNamedAloneIsItsMakeWhereAVehicleBelongs) {
  const auto brands = [](const std::string& s) { return agents::lexicon::find_brands(agents::text::words(s)); };
  ASSERT_EQ(brands("park a white transit in its spot").size(), 1u);
  EXPECT_EQ(brands("park a white transit in its spot")[0].brand, "ford");
  EXPECT_EQ(brands("put a prius behind the bus")[0].brand, "toyota");
  EXPECT_TRUE(brands("move into the escape lane").empty());   // a word, not a Ford
  EXPECT_TRUE(brands("public transit is slow").empty());      // no article: not in a vehicle's place
  LayoutChat park("blind-carpark");
  const auto state = park("a", "delete the truck and park a white Transit in its spot");
  ASSERT_EQ(state["added"].size(), 1u);
  EXPECT_NEAR(start_x(state["added"][0]), 100.0, 6.0);  // where the truck stood
}

TEST(TrafficState, PlacesPastAVehicleAtTheFarEndAndBesideABay) {
  LayoutChat queue("blind-queue");
  const auto past = queue("a", "add a green jeep parked past the truck")["added"][0];
  EXPECT_GT(start_x(past), 78.0);  // the truck stands at 75 m
  LayoutChat park("blind-carpark");
  EXPECT_GT(start_x(park("a", "put a police car at the far end of the aisle")["added"][0]), 50.0);
  // Beside a motorbike standing across its row: along the row, both of them, and not in one place.
  const auto two = park("b", "add two motorcycles parked in the bays next to the black motorbike")["added"];
  ASSERT_EQ(two.size(), 2u);
  for (const auto& m : two) {
    EXPECT_NEAR(start_y(m), 7.0, 1.0) << m;  // in the left row of bays
    EXPECT_LT(std::abs(start_x(m) - 8.0), 6.0) << m;
  }
  EXPECT_GT(std::abs(start_x(two[0]) - start_x(two[1])), 0.8);
}

TEST(TrafficState, TheViewMovesToTheJunctionAheadOrSaysThereIsNone) {
  LayoutChat park("blind-carpark");
  const auto view = park("a", "move the camera forward to the cross aisle")["view"];
  EXPECT_NEAR(view["translation_m"][0].get<double>(), 80.0, 3.0);
  LayoutChat ramp("blind-onramp");
  const auto state = ramp("a", "move the camera up to the junction");
  ASSERT_EQ(state["unresolved"].size(), 1u);
  EXPECT_EQ(state["view"]["translation_m"][0], 0.0);
}

TEST(TrafficState, APoliteRequestAfterSoIsWhatIsAsked) {
  LayoutChat park("blind-carpark");
  const auto added =
      park("a", "I want it to look busy, so could you fill the empty bays on the right with parked cars")["added"];
  ASSERT_GE(added.size(), 3u);
  for (const auto& v : added) EXPECT_EQ(v["intent"]["action"], "static") << v["intent"];
}

TEST(TrafficState, ComingUpBehindIsTowardTheEgoInEveryRound) {
  // Faster behind a stopped queue it is held up in its lane: never sent down the other way's lane.
  LayoutChat queue("blind-queue");
  queue("a", "add a white van in the left lane coming up behind us");
  const auto van = queue("a", "make it go faster")["added"][0];
  EXPECT_EQ(van["intent"]["lane"], "east_inner");
  EXPECT_GT(van["trajectory"][10]["x"].get<double>(), start_x(van));
}
