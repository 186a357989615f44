// How words bind to what they modify: angles to their own direction word, prepositional phrases
// to the phrase they sit in, verbs to the words right after them. Each test is a class of failure
// a blind set showed, not one of its cases.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "agents/asset/asset_choice.hpp"
#include "agents/deletion/deletion.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/decompose.hpp"
#include "agents/motion/motion_intent.hpp"
#include "agents/motion/planner.hpp"
#include "agents/view/view.hpp"

using namespace chatsim::agents;

TEST(LanguageBinding, EachAngleTakesTheAxisOfItsOwnDirectionWord) {
  const auto both = view::parse_view("look 10 degrees to the right and 5 degrees up");
  EXPECT_DOUBLE_EQ(*both.yaw_deg, -10);
  EXPECT_DOUBLE_EQ(*both.pitch_deg, 5);
  const auto listed = view::parse_view("pan left 20 degrees and tilt down 5 degrees");
  EXPECT_DOUBLE_EQ(*listed.yaw_deg, 20);
  EXPECT_DOUBLE_EQ(*listed.pitch_deg, -5);
  EXPECT_DOUBLE_EQ(*view::parse_view("tilt the camera 10 degrees").pitch_deg, 10);  // the verb says the axis
  EXPECT_FALSE(view::parse_view("tilt the camera 10 degrees").yaw_deg);
}

TEST(LanguageBinding, UpAndDownBeforeADeterminerSayWhereNotWhichWay) {
  const auto street = view::parse_view("swing the camera 45 degrees left to look down the side street");
  EXPECT_DOUBLE_EQ(*street.yaw_deg, 45);
  EXPECT_FALSE(street.pitch_deg);
  EXPECT_EQ(*view::parse_view("move the camera 10 m down the road").translation_m, (std::array<double, 3>{10, 0, 0}));
  EXPECT_EQ(*view::parse_view("bring it down a metre").translation_m, (std::array<double, 3>{0, 0, -1}));
}

TEST(LanguageBinding, TheDeletionVerbIsTheFirstNotAnOfLaterOn) {
  const auto d = deletion::parse_deletion("get rid of everything that's moving on my side of the road");
  ASSERT_EQ(d.targets.size(), 1u);
  EXPECT_EQ(d.targets[0].quantity, "all");
  EXPECT_EQ(d.targets[0].road_side, "near");
  EXPECT_TRUE(*d.targets[0].moving);
}

TEST(LanguageBinding, ANounAPrepositionGovernsIsNotWhatIsAdded) {
  const auto faster = asset::parse_asset("add a white mercedes in the left lane going much faster than the traffic");
  EXPECT_FALSE(faster.count);  // one car, not "traffic" (several)
  EXPECT_EQ(*faster.brand, "mercedes");
  EXPECT_EQ(asset::parse_asset("add a bus driving through the cars").type, "bus");
  // Unless nothing else names it.
  EXPECT_EQ(asset::parse_asset("turn it into a van").type, "van");
  EXPECT_EQ(asset::parse_asset("block all three lanes with barriers").type, "barrier");
}

TEST(LanguageBinding, APlaceFilledWithVehiclesIsARowParkedThere) {
  const auto in = manager::decompose("Make the parking on the left full of cars.");
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_EQ(asset::parse_asset(in[0].text).count, 4);
  const auto m = motion::parse_motion(in[0].text);
  EXPECT_EQ(m.lane, "parking");
  EXPECT_EQ(m.action, "static");
  // Traffic filling a side of the road is a busy road, not parked cars.
  EXPECT_EQ(manager::decompose("Fill the far side with heavy traffic coming toward me.")[0].kind, "busy_road");
}

TEST(LanguageBinding, FilteringRidesTheLaneEdgeTheLanesWay) {
  const auto m = motion::parse_motion("add a motorbike filtering between us and the oncoming traffic");
  EXPECT_EQ(m.lane_edge, "inner");
  EXPECT_NE(m.direction, "toward");  // what it filters beside is not where it goes
  EXPECT_NE(m.lane, "oncoming");
  EXPECT_EQ(m.action, "straight");
  EXPECT_EQ(manager::decompose("add a motorbike lane splitting beside me")[0].kind, "add");
}

TEST(LanguageBinding, AJunctionNamedAsAPlaceAlongTheRoadIsNoLane) {
  const auto m = motion::parse_motion("a red fire engine parked on the left-hand side just past the side street");
  EXPECT_FALSE(m.lane);
  EXPECT_EQ(m.placement, "left_front");  // by the junction ahead, not level with the ego
  EXPECT_FALSE(motion::parse_motion("put a roadblock across the road before the side street").lane);
  EXPECT_EQ(motion::parse_motion("a car coming out of the side street").lane, "cross");
  EXPECT_EQ(motion::parse_motion("a jam on the on-ramp").lane, "ramp");
  EXPECT_FALSE(motion::parse_motion("rush hour on my side of the road").lane);  // not the roadside
}

TEST(LanguageBinding, TheKerbIsOnTheSideTheRoadsTrafficKeepsTo) {
  const auto dir = std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts";
  const auto change = view::parse_view("move the viewpoint one metre closer to the kerb");
  EXPECT_DOUBLE_EQ(*change.toward_kerb_m, 1);
  const auto left_hand = chatsim::scene::load_scene(dir / "blind-lefthand");
  const auto right_hand = chatsim::scene::load_scene(dir / "blind-avenue");
  EXPECT_TRUE(view::keeps_left(left_hand));
  EXPECT_FALSE(view::keeps_left(right_hand));
  EXPECT_EQ(*view::resolve_on_map(change, left_hand).translation_m, (std::array<double, 3>{0, 1, 0}));
  EXPECT_EQ(*view::resolve_on_map(change, right_hand).translation_m, (std::array<double, 3>{0, -1, 0}));
}

TEST(LanguageBinding, WishesCorrectionsAndMovesOfWhatIsThere) {
  EXPECT_EQ(manager::decompose("I'd rather not have the motorbike behind me.")[0].kind, "delete");
  EXPECT_EQ(manager::decompose("Actually, make that 35 m.")[0].kind, "revise");
  const auto put = manager::decompose("Put it behind the grey car instead.");
  EXPECT_EQ(put[0].kind, "revise");
  EXPECT_EQ(put[0].target, "it");  // the grey car is where, not what
  // "70 m away" says how far, not which way.
  EXPECT_FALSE(motion::parse_motion("move it further up the street about 70 m away").direction);
  EXPECT_EQ(motion::parse_motion("a car 15 m behind us, same direction").direction, "toward");
}

TEST(LanguageBinding, MakesInThePluralAndQualifiedCars) {
  const auto rovers = asset::parse_asset("put two black range rovers parked one behind the other on the left");
  EXPECT_EQ(rovers.count, 2);
  EXPECT_EQ(rovers.brand, "landrover");
  const auto choice = asset::choose_asset(rovers);
  EXPECT_NE(std::find(choice.brand_words.begin(), choice.brand_words.end(), "land rover"), choice.brand_words.end());
  EXPECT_EQ(asset::parse_asset("add a red double-decker").type, "bus");
}

TEST(LanguageBinding, ChatShorthandAppositionsAndModelNumbers) {
  const auto hey = manager::decompose("hey, can u delete the red truck pls");
  ASSERT_EQ(hey.size(), 1u);
  EXPECT_EQ(hey[0].kind, "delete");
  EXPECT_EQ(*view::parse_view("camera 5m fwd").translation_m, (std::array<double, 3>{5, 0, 0}));
  EXPECT_EQ(manager::decompose("Everything parked across the street has to go.")[0].kind, "delete");
  // "make it an estate, a volvo v70": one revision, not a revision and a new car.
  const auto estate = manager::decompose("Make it an estate, a Volvo V70.");
  ASSERT_EQ(estate.size(), 1u);
  EXPECT_EQ(estate[0].kind, "revise");
  EXPECT_EQ(manager::decompose("Show an accident scene: police controlling the traffic ahead.")[0].kind, "road_block");
  EXPECT_EQ(asset::parse_asset("add a peugeot 308 estate").count.value_or(1), 1);  // the model number is no count
}

TEST(LanguageBinding, SelfCorrectionsAndTheCameraToANamedLane) {
  const auto corrected = manager::decompose("add a green tractor-trailer... no wait, a green truck, parked on the left");
  ASSERT_EQ(corrected.size(), 1u);
  EXPECT_EQ(corrected[0].kind, "add");
  EXPECT_EQ(corrected[0].text.find("trailer"), std::string::npos) << corrected[0].text;
  EXPECT_EQ(asset::parse_asset(manager::decompose("add a red car, I mean a blue van, 20 m ahead")[0].text).type, "van");
  EXPECT_EQ(manager::decompose("Sorry, remove the bus")[0].kind, "delete");  // an apology corrects nothing
  const auto avenue = chatsim::scene::load_scene(std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts/blind-avenue");
  const auto over = view::parse_view("move the camera over to the oncoming lane");
  EXPECT_EQ(over.to_lane, "oncoming");
  EXPECT_EQ(*view::resolve_on_map(over, avenue).translation_m, (std::array<double, 3>{0, 7, 0}));
  // From a view already 2 m to the left, the move is what is left to go.
  EXPECT_DOUBLE_EQ((*view::resolve_on_map(over, avenue, 2.0).translation_m)[1], 5.0);
}

TEST(LanguageBinding, QuestionsWithoutSomethingAndQuarterTurnsByName) {
  const auto without = manager::decompose("What would it look like without the red bus?");
  ASSERT_EQ(without.size(), 1u);
  EXPECT_EQ(without[0].kind, "delete");
  EXPECT_EQ(deletion::parse_deletion(without[0].text).targets[0].color, "red");
  EXPECT_DOUBLE_EQ(*view::parse_view("turn the camera to face left").yaw_deg, 90);
  EXPECT_DOUBLE_EQ(*view::parse_view("look right").yaw_deg, -90);
  EXPECT_FALSE(view::parse_view("move the camera 2 m to the left").yaw_deg);  // a move, not a turn
}

TEST(LanguageBinding, KeepingPaceWithTheEgoIsTheEgosSpeed) {
  EXPECT_EQ(motion::parse_motion("a white car in the left lane keeping pace with me").speed, "ego");
  EXPECT_EQ(motion::parse_motion("a van beside us at the same speed as us").speed, "ego");
  auto s = chatsim::scene::load_scene(std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts/blind-avenue");
  for (auto& f : s.frames) f.ego_to_world.translation().x() = 11.0 * f.timestamp_s;  // the ego at 11 m/s
  motion::PlanRequest req;
  req.intent = motion::parse_motion("a car in the left lane keeping pace with me");
  const auto r = motion::plan_motion(s, req);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_NEAR(r.speed_mps, 11.0, 0.1);
}

TEST(LanguageBinding, TheCarHeadingTheSameWayAsIt) {
  const auto d = deletion::parse_deletion("remove the oncoming bus and the car heading the same way as it");
  ASSERT_EQ(d.targets.size(), 2u);  // "as it" ends the relation, it is no third thing
  EXPECT_FALSE(d.unsupported);
  EXPECT_EQ(d.targets[1].of_previous, "same_way");
  const auto avenue = chatsim::scene::load_scene(std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts/blind-avenue");
  const auto chosen = deletion::select_objects(avenue, d, {});
  EXPECT_EQ(chosen.ids, (std::vector<std::string>{"obj_6", "obj_7"}));  // the westbound car and bus
}

TEST(LanguageBinding, AnUnknownNameWhereAVehicleBelongsIsACarOfUnknownMake) {
  if (!lexicon::is_english_word("the")) GTEST_SKIP() << "no English word list (wamerican): every word is unknown";
  const auto in = manager::decompose("Add a red Zastava Koral 20 m ahead.");  // a make vehicles.json lacks
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "add");  // not a view move because of the "20 m ahead"
  const auto r = asset::parse_asset(in[0].text);
  EXPECT_EQ(r.unknown_brand, "zastava koral");
  const auto choice = asset::choose_asset(r);
  EXPECT_EQ(choice.type, "car");
  ASSERT_TRUE(choice.note);
  EXPECT_NE(choice.note->find("zastava"), std::string::npos);  // said, not silently dropped
  EXPECT_EQ(manager::decompose("add a black zorblax at the front")[0].kind, "add");
  const auto van = asset::parse_asset("add a zorblax van 20 m ahead");  // before a noun too, in lower case
  EXPECT_EQ(van.unknown_brand, "zorblax");
  EXPECT_EQ(van.type, "van");
  EXPECT_FALSE(lexicon::unknown_vehicle_name(text::words("add a red car"), 1));
  // Deleting one: recorded objects carry no make, so it is refused with the name.
  EXPECT_EQ(deletion::parse_deletion("remove the zorblax").unsupported, "zorblax");
}
