// What a real recording is like, and blind set v22 (the nuScenes car park) showed: objects are
// labelled only once a sensor sees them, the road bends away from the ego's axis, vehicles park
// off every lane, and people say "coming my way", "following me", "everything on two wheels",
// "keep the black ones". Each class is tested on a small scene built here, not on v22's cases.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "agents/core/agent_registry.hpp"
#include "agents/llm/llm_backend.hpp"
#include "agents/manager/manager.hpp"
#include "common/scene/scene.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim;
using nlohmann::json;

namespace {

constexpr double kPi = std::numbers::pi;

// A road that runs 40 m along +x and bends right round a 20 m radius, then runs along -y; the
// ego lane is its centre, with a lane each side used both ways (as lanes derived from an ego path).
std::vector<Eigen::Vector3d> bent_road(double offset) {
  std::vector<Eigen::Vector3d> pts;
  for (double x = -30; x < 10; x += 2) pts.emplace_back(x, offset, 0);
  const double r = 20 - offset;
  for (double a = 0; a < kPi / 2; a += 0.05) pts.emplace_back(10 + r * std::sin(a), -20 + r * std::cos(a), 0);
  for (double y = -20; y >= -90; y -= 2) pts.emplace_back(30 - offset, y, 0);
  return pts;
}

scene::ObjectTrack parked(const std::string& id, const std::string& category, std::array<int, 3> rgb,
                          Eigen::Vector3d size, Eigen::Vector3d at, int from_frame, double yaw = 0) {
  scene::ObjectTrack o{id, category, rgb, size, {}};
  for (int f = from_frame; f < 101; ++f) o.track.push_back({f, at, yaw});
  return o;
}

std::string car_park_scene() {
  using namespace scene;
  Scene s;
  s.name = "car-park";
  s.source = "tests";
  s.layout_only = true;
  s.frame_rate_hz = 10;
  s.cameras.push_back(test_support::front_camera());
  for (int i = 0; i < 101; ++i) {  // the ego at 3 m/s along the straight, so it never reaches the bend
    Frame f;
    f.index = i;
    f.timestamp_s = 0.1 * i;
    f.ego_to_world.translation() = Eigen::Vector3d(0.3 * i, 0, 0);
    s.frames.push_back(f);
  }
  s.objects = {
      parked("bay_truck", "vehicle.truck", {120, 120, 120}, {5.8, 2.3, 3.0}, {6, -11, 1.5}, 0),
      parked("late_moto_black", "vehicle.motorcycle", {30, 30, 30}, {2.0, 0.7, 1.3}, {20, 10, 0.6}, 12),
      parked("late_moto_grey", "vehicle.motorcycle", {120, 120, 125}, {2.0, 0.7, 1.3}, {22, 10, 0.6}, 5),
      parked("late_black_car", "vehicle.car", {35, 35, 35}, {4.5, 1.8, 1.5}, {-12, -10, 0.75}, 30),
      parked("grey_car", "vehicle.car", {130, 130, 135}, {4.5, 1.8, 1.5}, {-4, -10, 0.75}, 0),
      parked("bicycle", "vehicle.bicycle", {60, 60, 60}, {1.8, 0.6, 1.1}, {14, 12, 0.5}, 0),
      parked("bus", "vehicle.bus.rigid", {200, 200, 200}, {12, 2.9, 3.4}, {-25, 12, 1.7}, 0),
      // Seen from frame 60 only, 8 m from the ego then, 21 m from where the clip starts.
      parked("late_white_car", "vehicle.car", {230, 230, 230}, {4.5, 1.8, 1.5}, {20, -8, 0.75}, 60),
  };
  std::vector<Lane> lanes;
  lanes.push_back({"ego_lane", "driving", 3.5, bent_road(0), TrafficDirection::Forward, {}});
  lanes.push_back({"left_of_ego", "driving", 3.5, bent_road(3.5), TrafficDirection::Both, {}});
  lanes.push_back({"right_of_ego", "driving", 3.5, bent_road(-3.5), TrafficDirection::Both, {}});
  s.lanes = LaneMap(std::move(lanes));
  const auto dir = chatsim::scratch::dir() / ("chatsim-car-park-" + std::to_string(::getpid()));
  save_scene(s, dir);
  return dir.string();
}

class RealScene : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { dir_ = new std::string(car_park_scene()); }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }
  json chat(const std::string& id, const std::string& command) { return manager_.chat(id, *dir_, command).edit_state; }
  static std::vector<std::string> removed(const json& state) {
    auto ids = state["removed"].get<std::vector<std::string>>();
    std::sort(ids.begin(), ids.end());
    return ids;
  }
  static const json& start(const json& state, size_t i = 0) { return state["added"][i]["trajectory"][0]; }

  static std::string* dir_;
  std::shared_ptr<agents::llm::Backend> backend_ = agents::llm::make_backend("offline");
  agents::manager::Manager manager_{agents::local_caller(backend_), backend_};
};
std::string* RealScene::dir_ = nullptr;

}  // namespace

TEST_F(RealScene, ObjectsLabelledOnlyOnceSeenCanBeSelected) {
  EXPECT_EQ(removed(chat("a", "delete the motorcycles")),
            (std::vector<std::string>{"late_moto_black", "late_moto_grey"}));
  EXPECT_EQ(removed(chat("b", "remove the black cars")), (std::vector<std::string>{"late_black_car"}));
  EXPECT_EQ(removed(chat("c", "remove the truck")), (std::vector<std::string>{"bay_truck"}));
}

TEST_F(RealScene, AheadFollowsTheRoadRoundItsBend) {
  // 55 m along the road is past the bend, 48 degrees off the ego's axis at 45 m: beyond the
  // straight-ahead window even when the planner looks twice as wide.
  const auto state = chat("a", "add a red car 55 m ahead");
  ASSERT_EQ(state["added"].size(), 1u) << state["unresolved"].dump();
  const double x = start(state)["x"], y = start(state)["y"];
  EXPECT_GT(x, 25);
  EXPECT_LT(y, -20);  // round the bend, not straight on into the car park
  EXPECT_NEAR(std::hypot(x, y), 45, 6);
}

TEST_F(RealScene, ParkedInTheSpotOfARemovedVehicleThatStoodOffTheLanes) {
  const auto state = chat("a", "remove the truck and park a green van there");
  EXPECT_EQ(removed(state), (std::vector<std::string>{"bay_truck"}));
  ASSERT_EQ(state["added"].size(), 1u) << state["unresolved"].dump();
  const auto& t = state["added"][0]["trajectory"];
  EXPECT_NEAR(t[0]["x"].get<double>(), 6, 0.01);
  EXPECT_NEAR(t[0]["y"].get<double>(), -11, 0.01);
  EXPECT_NEAR(t.back()["x"].get<double>(), 6, 0.01);  // it stays parked
}

TEST_F(RealScene, KeepingSomeOfWhatWasDeletedPutsThemBack) {
  chat("a", "delete all the motorcycles");
  EXPECT_EQ(removed(chat("a", "keep the black ones though")), (std::vector<std::string>{"late_moto_grey"}));
  chat("b", "remove the bus");
  EXPECT_TRUE(removed(chat("b", "keep the bus")).empty());
}

TEST_F(RealScene, EmptyingAndTwoWheelsSayWhatGoes) {
  EXPECT_EQ(removed(chat("a", "Empty the whole scene of vehicles.")).size(), 8u);
  EXPECT_EQ(removed(chat("b", "clear the scene of motorbikes")),
            (std::vector<std::string>{"late_moto_black", "late_moto_grey"}));
  EXPECT_EQ(removed(chat("c", "remove everything on two wheels")),
            (std::vector<std::string>{"bicycle", "late_moto_black", "late_moto_grey"}));
  EXPECT_EQ(removed(chat("d", "get rid of the two-wheelers")),
            (std::vector<std::string>{"bicycle", "late_moto_black", "late_moto_grey"}));
}

TEST_F(RealScene, ComingMyWayAndFollowingMeAreDirectionsAndPlaces) {
  auto state = chat("a", "add a taxi 20 m ahead coming my way");
  ASSERT_EQ(state["added"].size(), 1u) << state["unresolved"].dump();
  EXPECT_EQ(state["added"][0]["intent"]["direction"], "toward");
  const auto& t = state["added"][0]["trajectory"];
  EXPECT_LT(t[10]["x"].get<double>(), t[0]["x"].get<double>());  // it drives toward the ego
  state = chat("b", "add a black SUV following me");
  ASSERT_EQ(state["added"].size(), 1u) << state["unresolved"].dump();
  EXPECT_LT(start(state)["x"].get<double>(), -3);  // behind the ego
  EXPECT_GT(state["added"][0]["trajectory"][10]["x"].get<double>(), start(state)["x"].get<double>());
}

TEST_F(RealScene, AVehicleNounTypedWithADoubledLetterIsTheNoun) {
  // "buss" is in English word lists (a kiss), so the edit-distance typo fix leaves it alone.
  EXPECT_EQ(removed(chat("a", "remve the buss")), (std::vector<std::string>{"bus"}));
}

TEST_F(RealScene, NearestComparesDistancesAtOneTime) {
  // The late car is nearer the ego when it comes into view than the grey car is at the start, but
  // "nearest" compares them all from where the clip starts, as the user sees it.
  EXPECT_EQ(removed(chat("a", "delete the nearest car on my right")), (std::vector<std::string>{"grey_car"}));
  EXPECT_EQ(removed(chat("a", "and the next one along")), (std::vector<std::string>{"grey_car", "late_black_car"}));
}
