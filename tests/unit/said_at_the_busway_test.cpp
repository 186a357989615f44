// What blind set v29 showed, on a street with a busway and at a toll plaza: "the other side of"
// a named lane, one-word lane names ("the busway"), place words the map spells otherwise ("the toll
// lanes" on booth_1 ... booth_4), ordinal places ("the second booth"), people's nouns and riders,
// corrections said without a verb ("no wait, in front of it", "slower"), swapping a recorded
// vehicle for a new one, "it" from an earlier round, and the anchor that has what is placed by it.
// Each test is a class, not a case.
#include <gtest/gtest.h>

#include "agents/language/lane_names.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"
#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using namespace chatsim::agents;
using chatsim::testing::LayoutChat;
using chatsim::testing::removed_ids;
using nlohmann::json;
using Ids = std::vector<std::string>;

namespace {

double start_x(const json& state, size_t i) { return state["added"][i]["trajectory"][0]["x"].get<double>(); }

}  // namespace

TEST(SaidAtTheBusway, BeyondANamedLaneAndOneWordLaneNames) {
  // Busway lanes at y = 3.5 and 8.5 (obj_2, a bus, in the far one), the general westbound lane at
  // y = 12 (obj_5, obj_9, obj_10); a pedestrian (obj_8) on the platform between the busway lanes.
  LayoutChat street("blind-busway");
  EXPECT_EQ(removed_ids(street("a", "remove everything on the other side of the busway")), (Ids{"obj_10", "obj_5", "obj_9"}));
  EXPECT_EQ(removed_ids(street("b", "delete the vehicles beyond the bus lane")), (Ids{"obj_10", "obj_5", "obj_9"}));
  // A road is not such a place: "across the road" keeps its meaning (the other half of the road).
  EXPECT_FALSE(language::find_beyond_place(text::words("remove the cars across the road")));
  // "The busway is jammed with buses": buses, in the busway.
  const auto jam = street("c", "the busway is jammed with buses");
  ASSERT_GE(jam["added"].size(), 2u);
  for (const auto& v : jam["added"]) {
    EXPECT_EQ(v["category"], "vehicle.bus.rigid");
    EXPECT_EQ(v["intent"].value("lane_use", ""), "bus");
  }
  // A car asked for with no lane keeps out of the bus lane.
  const auto car = street("d", "add a red car ahead");
  ASSERT_EQ(car["added"].size(), 1u);
  EXPECT_NEAR(car["added"][0]["trajectory"][0]["y"].get<double>(), 0.0, 0.5);
}

TEST(SaidAtTheBusway, PlacesTheMapSpellsOtherwiseAndOrdinalPlaces) {
  // Lanes booth_1 ... booth_4; obj_1, obj_2 (a truck), obj_4 wait at booths 1, 3 and 4, obj_3 (a
  // blue car) behind the truck; obj_10, an orange truck on the far carriageway, is nearer the ego.
  LayoutChat plaza("blind-tollplaza");
  const auto cleared = removed_ids(plaza("a", "clear all the toll lanes"));
  for (const char* id : {"obj_1", "obj_2", "obj_3", "obj_4"}) EXPECT_NE(std::find(cleared.begin(), cleared.end(), id), cleared.end());
  EXPECT_EQ(std::find(cleared.begin(), cleared.end(), "obj_10"), cleared.end());
  const auto second = language::find_place_word(text::words("add a pickup waiting at the second booth"));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->use, "place:booth#2");
  const auto through = language::find_place_word(text::words("send a coach through booth 3"));
  ASSERT_TRUE(through);
  EXPECT_EQ(through->use, "place:booth#3");
  // Of the two trucks, the one with a car queuing behind it.
  EXPECT_EQ(removed_ids(plaza("b", "delete the car queuing behind the truck")), (Ids{"obj_3"}));
  // A distance from a vehicle that traffic leaves no room at: it goes further, and says so (the
  // truck stands 3.5 m in front of the blue car).
  const auto notes = plaza("d", "add a car 5 m in front of the blue car")["notes"].dump();
  EXPECT_NE(notes.find("nothing was free 5.0 m from the blue car"), std::string::npos) << notes;
  // "The toll booth attendant" is a person; "a guy on a motorbike" is the motorbike.
  EXPECT_EQ(removed_ids(plaza("c", "erase the toll booth attendant")), (Ids{"obj_8"}));
  const auto rider = lexicon::find_types(text::words("add a guy on a motorbike"));
  ASSERT_FALSE(rider.empty());
  EXPECT_EQ(rider.front().type.type, "motorcycle");
}

TEST(SaidAtTheBusway, CorrectionsWithoutAVerb) {
  using manager::detail::bare_change;
  using manager::detail::bare_place;
  EXPECT_EQ(bare_place(text::words("no, in front of it")).value_or(""), "in front of it");
  EXPECT_EQ(bare_change(text::words("a bit slower")).value_or(""), "a bit slower");
  EXPECT_FALSE(bare_change(text::words("go a bit faster")));  // the ego drives: the view's business
  EXPECT_FALSE(bare_place(text::words("behind the truck add a red car")));
  LayoutChat street("blind-busway");  // obj_1, the bendy bus, stands from x = 61 to 79
  street("a", "put a bus at the stop behind the bendy bus");
  const auto moved = street("a", "no wait, in front of it");
  ASSERT_EQ(moved["added"].size(), 1u);
  EXPECT_GT(start_x(moved, 0), 79.0);
  street("b", "add a red car 30 m ahead");
  EXPECT_LT(start_x(street("b", "a bit closer"), 0), 25.0);
}

TEST(SaidAtTheBusway, SwapsAndItFromAnEarlierRound) {
  LayoutChat street("blind-busway");
  const auto swapped = street("a", "swap the bendy bus for a double-decker");
  EXPECT_EQ(removed_ids(swapped), (Ids{"obj_1"}));
  ASSERT_EQ(swapped["added"].size(), 1u);
  EXPECT_EQ(swapped["added"][0]["category"], "vehicle.bus.rigid");
  EXPECT_NEAR(start_x(swapped, 0), 70.0, 3.0);
  // An added vehicle is revised, not removed and replaced.
  street("b", "add a red car");
  const auto revised = street("b", "replace the red car with a van");
  EXPECT_TRUE(revised["removed"].empty());
  ASSERT_EQ(revised["added"].size(), 1u);
  LayoutChat plaza("blind-tollplaza");
  plaza("c", "remove the truck at booth 3");
  EXPECT_EQ(removed_ids(plaza("c", "and the car behind it")), (Ids{"obj_2", "obj_3"}));
  EXPECT_EQ(removed_ids(plaza("c", "bring the truck back")), (Ids{"obj_3"}));
}
