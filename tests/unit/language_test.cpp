// The offline interpreter's parts: words and numbers, colours, and each agent's parser.
#include <filesystem>

#include <gtest/gtest.h>

#include "agents/asset/asset_choice.hpp"
#include "agents/deletion/deletion.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/llm/llm_backend.hpp"
#include "agents/manager/decompose.hpp"
#include "agents/motion/motion_intent.hpp"
#include "agents/view/view.hpp"

using namespace chatsim::agents;

TEST(Language, NumbersInDigitsAndWords) {
  auto q = text::quantities(text::words("move 2.5m ahead, then half a meter up and twenty five metres left"),
                            {"meters", "meter", "m"});
  ASSERT_EQ(q.size(), 3u);
  EXPECT_DOUBLE_EQ(q[0].value, 2.5);
  EXPECT_DOUBLE_EQ(q[1].value, 0.5);
  EXPECT_DOUBLE_EQ(q[2].value, 25);
  EXPECT_EQ(text::words("front-left, -3"), (std::vector<std::string>{"front", "left", "-3"}));
}

TEST(Language, ColourClassesFollowHueSaturationLightness) {
  EXPECT_EQ(lexicon::color_class({200, 30, 35}), "red");
  EXPECT_EQ(lexicon::color_class({240, 200, 20}), "yellow");
  EXPECT_EQ(lexicon::color_class({175, 178, 182}), "gray");
  EXPECT_EQ(lexicon::color_class({235, 235, 230}), "white");
  EXPECT_EQ(lexicon::color_class({20, 20, 22}), "black");
  EXPECT_EQ(lexicon::color_class({250, 110, 20}), "orange");
  // Every named colour we produce lands in the class of its base word.
  for (const char* c : {"red", "orange", "yellow", "green", "blue", "purple", "white", "black"}) {
    const auto m = lexicon::find_colors(text::words(std::string("a ") + c + " car"));
    ASSERT_EQ(m.size(), 1u) << c;
    EXPECT_EQ(lexicon::color_class(m[0].rgb), c);
  }
  EXPECT_EQ(lexicon::color_class(lexicon::find_colors(text::words("silver"))[0].rgb), "gray");
  EXPECT_EQ(lexicon::color_class(lexicon::find_colors(text::words("dark blue"))[0].rgb), "blue");
}

TEST(Language, ViewChanges) {
  auto v = view::parse_view("Shift the view 2 m to the right and 1 m up.");
  ASSERT_TRUE(v.translation_m);
  EXPECT_EQ(*v.translation_m, (std::array<double, 3>{0, -2, 1}));
  v = view::parse_view("Move back 3 meters");
  EXPECT_EQ(*v.translation_m, (std::array<double, 3>{-3, 0, 0}));
  v = view::parse_view("Look 15 degrees to the right");
  EXPECT_DOUBLE_EQ(*v.yaw_deg, -15);
  v = view::parse_view("Ego vehicle drives ahead slowly");
  EXPECT_EQ(v.ego_motion, "slow");
  EXPECT_FALSE(v.translation_m);
  const auto state = view::apply(view::apply({}, view::parse_view("move 5 m ahead")), view::parse_view("3 m up"));
  EXPECT_EQ(state.translation_m, (std::array<double, 3>{5, 0, 3}));
}

TEST(Language, MotionIntents) {
  auto m = motion::parse_motion("add a red porsche 20 meters ahead driving toward me fast");
  EXPECT_EQ(m.placement, "front");
  EXPECT_DOUBLE_EQ(*m.distance_m, 20);
  EXPECT_EQ(m.direction, "toward");
  EXPECT_EQ(m.speed, "fast");
  m = motion::parse_motion("add a green van driving at 50 km/h in the left lane");
  EXPECT_NEAR(*m.speed_mps, 50 / 3.6, 1e-9);
  EXPECT_EQ(m.lane, "left");
  EXPECT_FALSE(m.placement);  // a lane is not a side
  m = motion::parse_motion("add a police car also driving the wrong way and chasing behind the porsche");
  ASSERT_TRUE(m.relative);
  EXPECT_EQ(m.relative->to, "the porsche");
  EXPECT_EQ(m.relative->region, "back");
  EXPECT_TRUE(m.wrong_way.value_or(false));
  EXPECT_TRUE(m.chase.value_or(false));
  EXPECT_EQ(motion::parse_motion("an ambulance changing lanes to the left").action, "lane_change_left");
  EXPECT_EQ(motion::parse_motion("a silver tesla reversing slowly").action, "backward");
  EXPECT_EQ(motion::parse_motion("place a parked taxi on the right side 10 m ahead").placement, "right_front");
  // A revision steps the speed from where it was.
  motion::MotionIntent base;
  base.speed = "slow";
  base.merge(motion::parse_motion("make it faster"));
  EXPECT_EQ(base.speed, "normal");
}

TEST(Language, AssetsByTypeBrandAndColour) {
  auto r = asset::parse_asset("add a dark blue Porsche");
  EXPECT_EQ(r.brand, "porsche");
  EXPECT_EQ(r.type, "car");
  auto c = asset::choose_asset(r);
  EXPECT_EQ(c.asset, "porsche_911");
  EXPECT_EQ(lexicon::color_class(c.color_rgb), "blue");
  r = asset::parse_asset("add two traffic cones");
  EXPECT_EQ(r.type, "cone");
  EXPECT_EQ(r.count, 2);
  c = asset::choose_asset(asset::parse_asset("add a Zorbex car in front"));
  EXPECT_EQ(c.asset, "sedan");
  ASSERT_TRUE(c.note);
  EXPECT_NE(c.note->find("Zorbex"), std::string::npos);
  // Revising keeps what is not said.
  const auto base = asset::choose_asset(asset::parse_asset("a red taxi"));
  const auto truck = asset::choose_asset(asset::parse_asset("change it into a truck"), base);
  EXPECT_EQ(truck.type, "truck");
  EXPECT_EQ(lexicon::color_class(truck.color_rgb), "red");
}

TEST(Language, DeletionSelectors) {
  auto d = deletion::parse_deletion("Delete all vehicles except the truck");
  ASSERT_EQ(d.targets.size(), 1u);
  EXPECT_EQ(d.targets[0].quantity, "all");
  ASSERT_EQ(d.except.size(), 1u);
  EXPECT_EQ(d.except[0].category, "vehicle.truck");
  d = deletion::parse_deletion("Remove the yellow car and the green one");
  ASSERT_EQ(d.targets.size(), 2u);
  EXPECT_EQ(d.targets[1].color, "green");
  EXPECT_EQ(d.targets[1].category, "vehicle");
  d = deletion::parse_deletion("delete the second car on the left");
  EXPECT_EQ(d.targets[0].nth, 2);
  EXPECT_EQ(d.targets[0].region, "left");
  EXPECT_EQ(deletion::parse_deletion("Delete the purple helicopter").unsupported, "helicopter");
}

TEST(Language, CommandsSplitIntoInstructions) {
  auto in = manager::decompose(
      "Delete the bus, add an orange truck parked on the right 15 m ahead, and turn the view 10 degrees left.");
  ASSERT_EQ(in.size(), 3u);
  EXPECT_EQ(in[0].kind, "delete");
  EXPECT_EQ(in[1].kind, "add");
  EXPECT_EQ(in[2].kind, "view");
  in = manager::decompose("Add a Porsche ahead and a Mini on my left.");
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[1].text, "add a mini on my left");
  in = manager::decompose("Change it into a truck and make it faster.");
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[0].kind, "revise");
  EXPECT_EQ(in[1].kind, "revise");
  EXPECT_EQ(manager::decompose("Remove the Porsche I added.")[0].kind, "remove_added");
  EXPECT_EQ(manager::decompose("asdkj qwe zzz")[0].kind, "unclear");
  EXPECT_EQ(manager::decompose("Create a traffic jam.")[0].kind, "traffic_jam");
  EXPECT_EQ(manager::reference_in("make the added car turn left"), "the added car");
  EXPECT_EQ(manager::reference_in("make both of them black"), "both");
}

TEST(Language, OfflineAnswersMatchTheirSchemas) {
  auto backend = llm::make_backend("offline");
  for (const std::string agent : {"manager", "view", "deletion", "asset", "motion"}) {
    const auto out = backend->complete(llm::prompt_for(agent), "Remove all cars and add a red Porsche 20 m ahead.");
    EXPECT_EQ(llm::validate(out, llm::prompt_for(agent).schema), "") << agent;
  }
  EXPECT_THROW(llm::make_backend("no-such-backend"), llm::BackendError);
  const nlohmann::json schema = {{"type", "object"}, {"required", {"a"}}, {"additionalProperties", false},
                                 {"properties", {{"a", {{"enum", {"x", "y"}}}}}}};
  EXPECT_EQ(llm::validate({{"a", "x"}}, schema), "");
  EXPECT_NE(llm::validate({{"a", "z"}}, schema).find("$.a"), std::string::npos);
  EXPECT_NE(llm::validate({{"b", 1}, {"a", "x"}}, schema).find("unexpected field 'b'"), std::string::npos);
  EXPECT_NE(llm::validate(nlohmann::json::object(), schema).find("missing required field 'a'"), std::string::npos);
}

// The view agent's role function: offsets move every camera of every frame in the ego frame,
// yaw turns the rig about its own vertical, ego motion drives along the recorded path.
TEST(View, CameraPosesFollowTheOffsetsAndEgoMotion) {
  chatsim::scene::Scene s;
  chatsim::scene::Camera cam;
  cam.name = "front";
  cam.width = 100;
  cam.height = 100;
  cam.fx = cam.fy = 50;
  cam.sensor_to_ego.translation() = Eigen::Vector3d(1.5, 0, 1.6);
  s.cameras = {cam};
  for (int i = 0; i < 11; ++i) {
    chatsim::scene::Frame f;
    f.index = i;
    f.timestamp_s = 0.1 * i;
    f.ego_to_world.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();  // heading +y
    f.ego_to_world.translation() = Eigen::Vector3d(0, 1.0 * i, 0);
    s.frames.push_back(f);
  }
  view::ViewState v;
  v.translation_m = {5, 0, 0.5};
  auto poses = view::camera_poses(s, v);
  ASSERT_EQ(poses.size(), 11u);
  // 5 m ahead of an ego heading +y is +y in the world.
  EXPECT_LT((poses[3][0].translation() - Eigen::Vector3d(0, 3 + 5 + 1.5, 2.1)).norm(), 1e-9);
  v = {};
  v.yaw_deg = 90;
  poses = view::camera_poses(s, v);
  EXPECT_LT((poses[0][0].translation() - Eigen::Vector3d(-1.5, 0, 1.6)).norm(), 1e-9);  // rotated about the ego origin
  v = {};
  v.ego_motion = "slow";
  poses = view::camera_poses(s, v);
  EXPECT_NEAR(poses[10][0].translation().y(), 1.5 + view::ego_speed_mps("slow") * 1.0, 1e-9);
}

TEST(Language, MisspeltWordsAreReadAsTheDomainWordOneEditAway) {
  auto w = text::words("delte the motorcyle on the rigth, teh red one");
  lexicon::correct_typos(w);
  if (!std::filesystem::exists("/usr/share/dict/american-english")) GTEST_SKIP() << "no English word list (wamerican)";
  EXPECT_EQ(text::join(w), "delete the motorcycle on the right the red one");
  // English words are never "corrected", however near a domain word: faster is not master.
  auto english = text::words("make it faster in the lane");
  lexicon::correct_typos(english);
  EXPECT_EQ(text::join(english), "make it faster in the lane");
}

TEST(Language, MakesAndModelsComeFromTheVocabularyWithTheirBodyType) {
  const auto x5 = lexicon::find_brands(text::words("add a black BMW X5 30 m ahead"));
  ASSERT_EQ(x5.size(), 1u);
  EXPECT_EQ(x5[0].brand, "bmw");
  EXPECT_EQ(x5[0].type, "suv");
  EXPECT_EQ(x5[0].end - x5[0].begin, 2u);  // the model is part of the mention
  EXPECT_EQ(lexicon::find_brands(text::words("a Škoda Octavia"))[0].brand, "skoda");
  EXPECT_EQ(lexicon::find_brands(text::words("a toyota hilux pickup"))[0].type, "truck");
  EXPECT_EQ(lexicon::find_brands(text::words("the mazda mx-5"))[0].end, 4u);
  // A number after a make is a distance when a unit follows, not a model.
  EXPECT_EQ(lexicon::find_brands(text::words("a polestar 2 m ahead"))[0].end, 2u);
  // Makes that are ordinary words count only before a model or a vehicle noun.
  EXPECT_TRUE(lexicon::find_brands(text::words("take a seat by the man")).empty());
  EXPECT_EQ(lexicon::find_brands(text::words("a man truck")).size(), 1u);
}

TEST(Language, NumbersWithHalvesAndSymbols) {
  const auto q = text::quantities(text::words("raise it one and a half metres, back seven and a half m, look 10° right"),
                                  {"meters", "m", "degrees"});
  ASSERT_EQ(q.size(), 3u);
  EXPECT_DOUBLE_EQ(q[0].value, 1.5);
  EXPECT_DOUBLE_EQ(q[1].value, 7.5);
  EXPECT_DOUBLE_EQ(q[2].value, 10);
}

TEST(Language, ViewMovesInAListTakeTheDirectionOnTheSideTheUserWritesIt) {
  auto v = view::parse_view("move the camera forward 3 m, up 1 m and rotate 20 degrees left");
  EXPECT_EQ(*v.translation_m, (std::array<double, 3>{3, 0, 1}));
  EXPECT_DOUBLE_EQ(*v.yaw_deg, 20);
  v = view::parse_view("move the camera 3 m forward and 1 m up");
  EXPECT_EQ(*v.translation_m, (std::array<double, 3>{3, 0, 1}));
  v = view::parse_view("raise the camera 2 m and move it 1 m to the left");
  EXPECT_EQ(*v.translation_m, (std::array<double, 3>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(*view::parse_view("turn the view around").yaw_deg, 180);
  EXPECT_DOUBLE_EQ(*view::parse_view("look back 30 degrees to the left").yaw_deg, 30);
  EXPECT_EQ(manager::decompose("look behind me")[0].kind, "view");
  EXPECT_EQ(manager::decompose("make it turn around")[0].kind, "revise");
}

TEST(Language, AdditionsSaidInThePassiveOrWithANewSubject) {
  auto in = manager::decompose("A navy Genesis GV80 should be added about forty-five metres ahead.");
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_EQ(in[0].text, "add a navy genesis gv80 about forty five meters ahead");
  in = manager::decompose("I want a white van placed behind me");
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_EQ(in[0].text, "add a white van behind me");  // the wish goes with the passive
  EXPECT_EQ(manager::decompose("a pickup should come out of the side street")[0].kind, "add");
  // Not new: a vehicle named with "the", a pronoun, or a number that is an amount.
  EXPECT_EQ(manager::decompose("the added car should be placed 10 m further ahead")[0].kind, "revise");
  EXPECT_EQ(manager::decompose("now also 2 m forward")[0].kind, "view");
  EXPECT_EQ(manager::decompose("repaint it orange")[0].kind, "revise");
  EXPECT_EQ(manager::decompose("respray the van green")[0].kind, "revise");
  EXPECT_EQ(manager::decompose("set up a road block at the junction")[0].kind, "road_block");
}

TEST(Language, SisterBrandsAndOrdinaryWordMakes) {
  // "cupra" is only a make; "seat" is also a word, a make only before a model or a noun.
  const auto cupra = lexicon::find_brands(text::words("delete the cupra"));
  ASSERT_EQ(cupra.size(), 1u);
  EXPECT_EQ(cupra[0].brand, "seat");
  EXPECT_TRUE(lexicon::find_brands(text::words("take a seat")).empty());
  EXPECT_FALSE(lexicon::find_brands(text::words("a seat ibiza")).empty());
}

TEST(Language, DeletionByOrderAlongTheRowAndByAnotherObject) {
  auto d = deletion::parse_deletion("remove the last parked car on the right");
  ASSERT_EQ(d.targets.size(), 1u);
  EXPECT_EQ(d.targets[0].order, "farthest");
  d = deletion::parse_deletion("remove the car parked closest to the police car");
  ASSERT_EQ(d.targets.size(), 2u);
  EXPECT_TRUE(d.targets[0].anchor_only);
  EXPECT_EQ(d.targets[0].category, "vehicle.emergency.police");
  EXPECT_EQ(d.targets[1].of_previous, "near");
  EXPECT_FALSE(d.targets[1].moving.value_or(true));
  d = deletion::parse_deletion("delete the van behind the bus");
  ASSERT_EQ(d.targets.size(), 2u);
  EXPECT_EQ(d.targets[1].of_previous, "behind");
  // A place named after a vehicle is no object to place by.
  EXPECT_EQ(deletion::parse_deletion("delete the car in front of the bus stop").targets.size(), 1u);
}

TEST(Language, LaneEdgesAreLanesNotVehiclesToPlaceBy) {
  auto m = motion::parse_motion("add an suv coming toward me on the far side in the lane next to the median");
  EXPECT_EQ(m.lane_edge, "inner");
  EXPECT_FALSE(m.relative);
  EXPECT_EQ(m.lane, "oncoming");
  m = motion::parse_motion("a truck in the slow lane");
  EXPECT_EQ(m.lane_edge, "outer");
  EXPECT_FALSE(m.speed);
  m = motion::parse_motion("a van parked next to the kerb");
  EXPECT_FALSE(m.lane_edge);
  EXPECT_EQ(m.lane, "parking");
}

TEST(Language, DeletionsByRoadSideListsAndWishes) {
  auto d = deletion::parse_deletion("wipe out every parked vehicle on my side");
  ASSERT_EQ(d.targets.size(), 1u);
  EXPECT_EQ(d.targets[0].road_side, "near");
  EXPECT_EQ(deletion::parse_deletion("take out whatever is parked across the road").targets[0].road_side, "far");
  // The commas are gone by then: a determiner right after a noun starts the next phrase.
  d = deletion::parse_deletion("remove the red car the truck and the motorbike");
  ASSERT_EQ(d.targets.size(), 3u);
  EXPECT_EQ(d.targets[1].category, "vehicle.truck");
  EXPECT_EQ(manager::decompose("I don't want the white car in the shot")[0].kind, "delete");
  // "get" is a deletion only with rid/out/away; "get it to ..." asks it to do something.
  EXPECT_EQ(manager::decompose("get rid of the bus")[0].kind, "delete");
  EXPECT_EQ(manager::decompose("get it to drive off")[0].kind, "revise");
}

TEST(Language, ViewPhrasalVerbsAndLaneWidths) {
  EXPECT_EQ(*view::parse_view("back the camera up five metres and bring it down a metre").translation_m,
            (std::array<double, 3>{-5, 0, -1}));
  EXPECT_EQ(*view::parse_view("move the camera to the left by two lanes").translation_m,
            (std::array<double, 3>{0, 7, 0}));
}

TEST(Language, CopiesAttributesAndPoliceControls) {
  auto in = manager::decompose("another one behind that");
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_EQ(in[0].target, "it");  // a copy of the vehicle spoken about last
  EXPECT_EQ(manager::decompose("change the colour to dark green")[0].kind, "revise");
  EXPECT_EQ(manager::decompose("I want the police stopping traffic up ahead")[0].kind, "road_block");
}

TEST(Language, RequestsWishesTitlesAndEnumerations) {
  EXPECT_EQ(manager::decompose("Could we have a Volkswagen Golf in the side street?")[0].kind, "add");
  EXPECT_EQ(manager::decompose("the motorbike behind me has to go")[0].kind, "delete");
  EXPECT_EQ(manager::decompose("Take the camera 5 m further back")[0].kind, "view");
  EXPECT_EQ(manager::decompose("Put it 20 m further back.")[0].kind, "revise");
  EXPECT_EQ(manager::decompose("Put the bus back.")[0].kind, "restore");
  auto in = manager::decompose("Now a grey one behind it.");
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_EQ(in[0].target, "it");
  // A title before a colon goes when the detail after it does the work; a bare plural after a
  // comma in an addition is added too.
  in = manager::decompose("Simulate a breakdown: a broken-down van in my lane 35 m ahead, cones behind it.");
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_EQ(in[1].kind, "add");
  EXPECT_EQ(in[1].text, "add cones behind it");
  EXPECT_EQ(manager::decompose("remove the trucks, cars and vans").size(), 1u);
  // "a quarter turn" is an angle.
  EXPECT_EQ(manager::decompose("look right by a quarter turn")[0].text, "look right by 90 degrees");
}

TEST(Language, ReferencesEndWithTheirNounAndWaitingVehiclesStand) {
  auto m = motion::parse_motion("put a ford mustang in front of the silver car doing 60 km/h");
  ASSERT_TRUE(m.relative);
  EXPECT_EQ(m.relative->to, "the silver car");
  EXPECT_NEAR(*m.speed_mps, 60 / 3.6, 1e-9);
  EXPECT_EQ(motion::parse_motion("a cement mixer waiting at the junction to turn right").action, "static");
  EXPECT_EQ(motion::parse_motion("a truck that waits, then turns right").action, "turn_right");
  // An explicit turn out of a side street stands; without one the road decides (join).
  EXPECT_EQ(motion::parse_motion("a car pulls out of the side street on the left and turns right").action, "turn_right");
  EXPECT_EQ(motion::parse_motion("a car coming out of the side street").action, "join");
  const auto cement = lexicon::find_types(text::words("a cement mixer"));
  ASSERT_EQ(cement.size(), 1u);
  EXPECT_EQ(cement[0].type.type, "truck");
  EXPECT_EQ(lexicon::find_types(text::words("a people carrier"))[0].type.type, "van");
}

TEST(Language, TopicsCausativesContinuationsAndViewVerbs) {
  // A topic named first, then "delete it".
  auto in = manager::decompose("The red car behind us - delete it.");
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "delete");
  EXPECT_EQ(in[0].text, "delete the red car behind us");
  // A new vehicle made to do something, and a motion with no subject that belongs to it.
  in = manager::decompose("Have a Chevrolet Tahoe come from the right on the cross road and turn left in front of us.");
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_NE(in[0].text.find("turn left in front of us"), std::string::npos);
  // "it" after a view clause is the camera, whatever the verb.
  in = manager::decompose("Turn the camera to look left 20 degrees and drop it 0.3 m.");
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[1].kind, "view");
  EXPECT_EQ(manager::decompose("Place the viewpoint one lane to the right.")[0].kind, "view");
  in = manager::decompose("put a scooter in the right lane 20 m ahead and lift the camera by 80 cm");
  ASSERT_EQ(in.size(), 2u);
  EXPECT_EQ(in[1].kind, "view");
  in = manager::decompose("add a white one behind it");
  EXPECT_EQ(in[0].target, "it");
  // People stand; they do not park.
  const auto d = deletion::parse_deletion("remove everything parked on my right");
  ASSERT_EQ(d.except.size(), 1u);
  EXPECT_EQ(d.except[0].category, "human");
}

TEST(Language, BesideTheEgoAndChasesThatStartFromParked) {
  auto m = motion::parse_motion("add a gold lexus es in the right lane alongside me");
  EXPECT_EQ(m.placement, "right");
  motion::MotionIntent parked = motion::parse_motion("a police car parked behind the black car");
  ASSERT_EQ(parked.action, "static");
  parked.merge(motion::parse_motion("chase the red car"));
  EXPECT_FALSE(parked.action == "static");
  EXPECT_FALSE(parked.speed == "static");
}

TEST(Language, HalvesAfterUnitsCopiesAndParkedMeansAtTheKerb) {
  const auto q = text::quantities(text::words("raise the view by a metre and a half"), {"meters", "meter", "m"});
  ASSERT_EQ(q.size(), 1u);
  EXPECT_DOUBLE_EQ(q[0].value, 1.5);
  EXPECT_EQ(manager::decompose("Add another behind the cab.")[0].target, "it");  // another of the last one
  EXPECT_EQ(manager::decompose("Add another cab behind it.")[0].target, "");     // a cab of its own
  // "crossing the road" is what the person does, not a lane.
  EXPECT_FALSE(deletion::parse_deletion("get rid of the person crossing the road").targets[0].lane);
  EXPECT_TRUE(deletion::parse_deletion("delete the two cars parked nearest the cone").targets[1].parked);
}

TEST(Language, PlacesNamedAfterVehiclesSisterBrandsRampsAndAngles) {
  // "the bus bay" is a place; "make it park in the bus bay" does not make it a bus.
  EXPECT_TRUE(lexicon::find_types(text::words("park in the bus bay")).empty());
  EXPECT_EQ(asset::parse_asset("make it park in the bus bay").type, std::nullopt);
  // A make said by another of its names keeps that name as a label.
  const auto corsa = asset::choose_asset(asset::parse_asset("a dark blue vauxhall corsa"));
  EXPECT_NE(std::find(corsa.brand_words.begin(), corsa.brand_words.end(), "vauxhall"), corsa.brand_words.end());
  EXPECT_EQ(deletion::parse_deletion("remove the car joining from the slip road").targets[0].lane, "ramp");
  EXPECT_EQ(deletion::parse_deletion("delete the broken-down car on the hard shoulder").targets[0].lane, "shoulder");
  EXPECT_FALSE(*deletion::parse_deletion("delete the broken-down car").targets[0].moving);
  // The side word of an angle is the turn's, not the next distance's.
  const auto v = view::parse_view("pan right 20 degrees and go 10 m ahead");
  EXPECT_EQ(*v.translation_m, (std::array<double, 3>{10, 0, 0}));
  EXPECT_DOUBLE_EQ(*v.yaw_deg, -20);
  EXPECT_EQ(manager::decompose("create a jam on the on ramp")[0].kind, "traffic_jam");
  EXPECT_EQ(manager::decompose("now add a red one in front of the truck")[0].target, "it");
}

TEST(Language, RowsScenesKerbsTallCarsAndPairs) {
  EXPECT_EQ(asset::parse_asset("a row of parked cars on the left").count, 4);
  auto in = manager::decompose("Make it look like school's out: a row of parked cars on the left.");
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].kind, "add");
  EXPECT_DOUBLE_EQ(*view::parse_view("move the camera 2 m closer to the kerb").toward_kerb_m, 2);
  auto d = deletion::parse_deletion("delete both cars parked at the kerb");
  EXPECT_EQ(d.targets[0].quantity, "n");
  EXPECT_EQ(d.targets[0].n, 2);
  EXPECT_EQ(deletion::parse_deletion("remove the parked cars on both sides").targets[0].quantity, "all");
  // "about to merge" moves; "about to pull out" stands.
  EXPECT_NE(motion::parse_motion("a car on the slip road about to merge").action, "static");
  EXPECT_EQ(motion::parse_motion("a van about to pull out").action, "static");
}
