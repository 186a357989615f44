// What blind set v30 showed, at a level crossing and a drive-thru: a railway crossing as a place,
// queues named by their place and counted along themselves ("the last car in the line"), a place
// emptied ("empty the drive-thru"), corrections said as "I meant ..." or with a distance alone,
// a speed said by another vehicle's, makes the vocabulary lacked kept as names, lists parted by
// slashes, and the recording car's own path. Each test is a class, not a case.
#include <gtest/gtest.h>

#include "agents/language/lane_names.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"
#include "agents/manager/decompose.hpp"
#include "agents/motion/motion_intent.hpp"
#include "tests/unit/layout_chat.hpp"

using namespace chatsim;
using namespace chatsim::agents;
using chatsim::testing::LayoutChat;
using chatsim::testing::removed_ids;
using nlohmann::json;
using Ids = std::vector<std::string>;

namespace {

std::vector<std::string> kinds(const std::string& command) {
  std::vector<std::string> out;
  for (const auto& in : manager::decompose(command)) out.push_back(in.kind);
  return out;
}

}  // namespace

TEST(SaidAtTheCrossing, ARailwayCrossingIsAPlaceAndAQueueIsEveryoneInIt) {
  // A railway crosses the road at x = 78: obj_1 (x = 71) and obj_2 (x = 64) wait at it in the
  // ego's lane; obj_8, a 4x4, stands alone on a farm track 57 m away, nearer than obj_1.
  LayoutChat crossing("blind-levelcrossing");
  EXPECT_EQ(removed_ids(crossing("a", "remove the two vehicles waiting at the level crossing")), (Ids{"obj_1", "obj_2"}));
  EXPECT_EQ(removed_ids(crossing("b", "clear the queue at the barrier")), (Ids{"obj_1", "obj_2"}));
  // A vehicle standing alone is no queue: the front of the queue is obj_1, not the 4x4.
  EXPECT_EQ(removed_ids(crossing("c", "remove the car at the front of the queue")), (Ids{"obj_1"}));
  // "The barrier" alone is a thing to remove or add, not a place.
  EXPECT_FALSE(language::find_lane_name(text::words("remove the barrier")));
  EXPECT_EQ(language::find_lane_name(text::words("the cars waiting at the barrier"))->use, "rail_crossing");
}

TEST(SaidAtTheCrossing, QueuesNamedByTheirPlaceAndCountedAlongThemselves) {
  // The drive-thru queue: obj_1 at the window (x = 95), obj_2, then obj_3 at its back (x = 81.5);
  // obj_4 drives ahead of the ego on the street; obj_5 is parked in the car park.
  LayoutChat drive("blind-drivethru");
  EXPECT_EQ(removed_ids(drive("a", "remove the drive-thru queue")), (Ids{"obj_1", "obj_2", "obj_3"}));
  EXPECT_EQ(removed_ids(drive("b", "remove the last car in the drive-thru line")), (Ids{"obj_3"}));
  EXPECT_EQ(removed_ids(drive("c", "remove the first car in the queue")), (Ids{"obj_1"}));
  EXPECT_EQ(removed_ids(drive("d", "empty the drive-thru")), (Ids{"obj_1", "obj_2", "obj_3"}));
  // "The last car" with no queue said is still the farthest.
  EXPECT_EQ(removed_ids(drive("e", "remove the last car")), (Ids{"obj_1"}));
  // Joining the back of the queue: behind obj_3, standing, not behind the ego.
  const auto joined = drive("f", "add a green Genesis GV80 joining the back of the drive-thru queue");
  ASSERT_EQ(joined["added"].size(), 1u);
  const auto& start = joined["added"][0]["trajectory"][0];
  EXPECT_NEAR(start["y"].get<double>(), -12.0, 0.5);
  EXPECT_GT(start["x"].get<double>(), 65.0);
  EXPECT_LT(start["x"].get<double>(), 80.0);
  EXPECT_EQ(joined["added"][0]["intent"]["action"], "static");
}

TEST(SaidAtTheCrossing, CorrectionsSaidAsIMeantOrAsADistanceAlone) {
  EXPECT_EQ(manager::detail::meant_correction(text::words("sorry i meant a kia sorento")), "make it a kia sorento");
  EXPECT_EQ(manager::detail::meant_correction(text::words("i meant behind it")), "put it behind it");
  EXPECT_FALSE(manager::detail::meant_correction(text::words("i meant it")));
  EXPECT_EQ(manager::detail::bare_place(text::words("no 30 m behind")), "30 m behind");
  // "In the car park": the place's own words ("park") are no verb.
  EXPECT_EQ(manager::detail::bare_place(text::words("no in the car park")), "in the car park");
  LayoutChat drive("blind-drivethru");
  drive("a", "add a white Kia Sportage behind the black car");
  EXPECT_EQ(drive("a", "sorry, I meant a Kia Sorento")["added"].size(), 1u);
  // After a deletion, "I meant the motorbike" is that deletion, of the motorbike.
  drive("b", "remove the truck");
  EXPECT_EQ(removed_ids(drive("b", "sorry, I meant the motorbike")), (Ids{"obj_6"}));
  // Moved to a parking place with no motion said: it parks there.
  drive("c", "put a van ahead");
  const auto parked = drive("c", "no, in the car park");
  EXPECT_EQ(parked["added"][0]["intent"]["lane"], "car_park");
  EXPECT_EQ(parked["added"][0]["intent"]["action"], "static");
}

TEST(SaidAtTheCrossing, ASpeedSaidByAnotherVehicles) {
  const auto twice = motion::parse_motion("add a car ahead driving twice as fast as the cyclist");
  EXPECT_EQ(twice.speed_of, "the cyclist");
  EXPECT_EQ(twice.speed_factor, 2.0);
  EXPECT_EQ(motion::parse_motion("add a car 3 times as fast as me").speed, "ego");
  // No one vehicle's speed: a speed word, as before.
  const auto traffic = motion::parse_motion("add a car going much faster than the traffic");
  EXPECT_FALSE(traffic.speed_of);
  EXPECT_EQ(traffic.speed, "faster");
  // The cyclist rides at 3.5 m/s: the car drives at 7, and is a car (the cyclist only says how fast).
  LayoutChat crossing("blind-levelcrossing");
  const auto car = crossing("a", "add a white Cupra Born ahead of us driving twice as fast as the cyclist");
  ASSERT_EQ(car["added"].size(), 1u);
  EXPECT_EQ(car["added"][0]["category"], "vehicle.car");
  EXPECT_NEAR(car["added"][0]["intent"]["speed_mps"].get<double>(), 7.0, 0.01);
  // A vehicle that is not there: said, and a faster speed than usual.
  const auto missing = crossing("b", "add a car ahead going twice as fast as the tram");
  EXPECT_NE(missing["notes"].dump().find("to take the speed of"), std::string::npos);
}

TEST(SaidAtTheCrossing, NamesTheVocabularyLacksAndListsPartedBySlashes) {
  // "Lada" is one letter from "lady": said with a capital, it is a name, never a typo.
  EXPECT_EQ(text::capitalised_words("Add a Lada Niva behind the Tractor"), (std::set<std::string>{"lada", "niva", "tractor"}));
  const auto lada = manager::decompose("add a Zastava behind the tractor");
  ASSERT_EQ(lada.size(), 1u);
  EXPECT_EQ(lada[0].kind, "add");
  EXPECT_EQ(kinds("turn the camera 30 degrees to the left / remove the van / add a bus behind us"),
            (std::vector<std::string>{"view", "delete", "add"}));
  EXPECT_EQ(kinds("add a car at 50 km/h"), (std::vector<std::string>{"add"}));  // "km/h" keeps its slash
  EXPECT_EQ(kinds("del: motorbike"), (std::vector<std::string>{"delete"}));
}

TEST(SaidAtTheCrossing, TheRecordingCarsPathIsSaidWhenItMeetsAnAddedVehicle) {
  // The ego drives its lane at 4.5 m/s from x = 0; a car stopped 10 m ahead in that lane is met by
  // the recorded drive, which cannot give way: a note says when.
  LayoutChat crossing("blind-levelcrossing");
  const auto stopped = crossing("a", "add a car stopped in my lane 10 m ahead");
  EXPECT_NE(stopped["notes"].dump().find("the recorded drive runs into it"), std::string::npos);
}
