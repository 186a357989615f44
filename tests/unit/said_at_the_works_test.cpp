// What blind set v28 showed, at roadworks and a petrol station: a lane named by what closes it
// ("the coned-off lane"), places named by the map's own words ("at the pumps", "pump 2", "the gas
// station"), distances in car lengths, in seconds and from another vehicle, numeric ordinals, a
// removal whose detail follows a colon, works already there being a place rather than a scene to
// build, "the far side", "the other lane", "chase us". Each test is a class, not a case.
#include <gtest/gtest.h>

#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using chatsim::testing::LayoutChat;
using chatsim::testing::removed_ids;
using nlohmann::json;

namespace {

double start_x(const json& state, size_t i) { return state["added"][i]["trajectory"][0]["x"].get<double>(); }
double start_y(const json& state, size_t i) { return state["added"][i]["trajectory"][0]["y"].get<double>(); }

}  // namespace

TEST(SaidAtTheWorks, ClosedLanesOrdinalsAndAListAfterAColon) {
  // The right eastbound lane (y = -3.5) holds cones, a digger (obj_1), a dumper (obj_2, a truck)
  // and a trailer (obj_12); obj_9 a red car 15 m behind in the ego's lane, obj_13 a motorbike 30 m.
  LayoutChat works("blind-roadworks");
  EXPECT_EQ(removed_ids(works("a", "delete every vehicle in the blocked lane")),
            (std::vector<std::string>{"obj_1", "obj_12", "obj_2"}));
  EXPECT_EQ(removed_ids(works("b", "empty the works area: the trailer and the dumper")),
            (std::vector<std::string>{"obj_12", "obj_2"}));
  EXPECT_EQ(removed_ids(works("c", "remove the 1st car behind me")), (std::vector<std::string>{"obj_9"}));
  // Works already there are a place: one van parked in that lane, no cones and barriers built.
  const auto van = works("d", "add a van parked in the coned-off lane");
  ASSERT_EQ(van["added"].size(), 1u);
  EXPECT_NEAR(start_y(van, 0), -3.5, 0.5);
  // "Remove the roadworks sign": nothing is built; no sign is in the scene, so it is refused.
  const auto sign = works("e", "remove the roadworks sign");
  EXPECT_TRUE(sign["added"].empty());
  EXPECT_FALSE(sign["unresolved"].empty());
}

TEST(SaidAtTheWorks, DistancesInCarLengthsInSecondsAndFromAVehicle) {
  LayoutChat works("blind-roadworks");  // obj_8 a white van 22 m ahead in the ego's lane
  const auto back = works("a", "move the camera back three car lengths")["view"]["translation_m"];
  EXPECT_NEAR(back[0].get<double>(), -13.5, 0.01);
  EXPECT_NEAR(start_x(works("b", "add a red car 10 m behind the van"), 0), 12.0, 1.5);
  // A unit of length names no vehicle: the camera moves on, and the vehicle added is no bus.
  const auto on = works("c", "raise the camera 2 m and move it two car lengths forward")["view"]["translation_m"];
  EXPECT_NEAR(on[0].get<double>(), 9.0, 0.01);
  EXPECT_NEAR(on[2].get<double>(), 2.0, 0.01);
  const auto behind = works("d", "add a vehicle 2 bus lengths behind me");
  ASSERT_EQ(behind["added"].size(), 1u);
  EXPECT_EQ(behind["added"][0]["category"], "vehicle.car");
  EXPECT_NEAR(start_x(behind, 0), -24.0, 3.0);
  LayoutChat fuel("blind-fuel");  // the ego drives at 8 m/s
  EXPECT_NEAR(start_x(fuel("a", "add a car 2 seconds ahead of me"), 0), 16.0, 2.0);
}

TEST(SaidAtTheWorks, PlacesTheMapNamesTheFarSideAndTheOtherLane) {
  // Pump lanes at y = -9 and -13 (x 30-50, obj_1-3), a tanker bay y = -17 (obj_4), the exit road
  // (obj_5 waits there); parking on the far side of the road at y = 6.5.
  LayoutChat fuel("blind-fuel");
  EXPECT_EQ(removed_ids(fuel("a", "delete the motorbike at the pumps")), (std::vector<std::string>{"obj_3"}));
  EXPECT_EQ(removed_ids(fuel("b", "remove all the cars at the petrol station")),
            (std::vector<std::string>{"obj_1", "obj_2", "obj_3", "obj_4", "obj_5"}));
  const auto pump = fuel("c", "add a car parked at pump two");
  ASSERT_EQ(pump["added"].size(), 1u);
  EXPECT_NEAR(start_y(pump, 0), -13.0, 0.5);
  EXPECT_NEAR(start_y(fuel("d", "add a van parked on the far side of the street"), 0), 6.5, 0.5);
  const auto busy = fuel("e", "the forecourt is really busy");
  ASSERT_GE(busy["added"].size(), 2u);
  for (const auto& a : busy["added"]) EXPECT_LT(a["trajectory"][0]["y"].get<double>(), -5.0);  // at the station
  EXPECT_NEAR(fuel("f", "let me see this from the other lane")["view"]["translation_m"][1].get<double>(), 3.5, 0.3);
  fuel("g", "add an ambulance behind us");
  const auto chase = fuel("g", "make it chase us")["added"];
  ASSERT_EQ(chase.size(), 1u);
  EXPECT_GT(chase[0]["trajectory"].back()["x"].get<double>(), 60.0);  // the ego's way, fast
}
