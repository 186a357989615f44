// The decision pipeline end to end (in-process) on graded command cases: the shared dev cases
// and our own paraphrases (tests/data), which guard against fitting the dev phrasing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <tuple>

#include "agents/core/agent_registry.hpp"
#include "bench/command_grader.hpp"
#include "common/import/nuscenes_import.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim;
namespace fs = std::filesystem;

namespace {

// Cases the system cannot do as asked on that scene, each with what it must say instead: the
// text its notes or unresolved reasons carry (so a silent failure still fails the test).
using Exceptions = std::map<std::string, std::string>;

bool says(const nlohmann::json& state, const std::string& text) {
  for (const auto* list : {&state["notes"], &state["unresolved"]})
    for (const auto& n : *list)
      if ((n.is_string() ? n.get<std::string>() : n.value("reason", "")).find(text) != std::string::npos) return true;
  return false;
}

void run_cases(const fs::path& cases_file, const fs::path& scene_dir, const Exceptions& exceptions = {}) {
  const auto scene = scene::load_scene(scene_dir);
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  agents::manager::Manager manager(agents::local_caller(backend), backend);
  std::ifstream in(cases_file);
  ASSERT_TRUE(in) << cases_file;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto c = nlohmann::json::parse(line);
    nlohmann::json state;
    for (const auto& r : c["rounds"]) state = manager.chat(c["id"], scene_dir, r.get<std::string>()).edit_state;
    const auto id = c["id"].get<std::string>();
    if (const auto e = exceptions.find(id); e != exceptions.end()) {
      EXPECT_TRUE(says(state, e->second)) << id << " should say '" << e->second << "': " << state["notes"].dump()
                                          << state["unresolved"].dump();
    } else {
      for (const auto& r : bench::grade_case(scene, state, c["expect"]))
        EXPECT_TRUE(r.pass) << id << ": " << r.check << ": " << r.detail;
    }
    ++n;
  }
  EXPECT_GT(n, 20);
}

// Accuracy of a case file whose cases name their scenes (a 'scene' path relative to the file),
// and whether any added vehicle meets another.
struct SetScore {
  int passed = 0, total = 0, vehicles = 0, overlapping = 0;
};

SetScore score_set(const fs::path& cases_file, const std::optional<fs::path>& scene_dir = std::nullopt) {
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  agents::manager::Manager manager(agents::local_caller(backend), backend);
  std::map<std::string, scene::Scene> scenes;
  std::ifstream in(cases_file);
  SetScore out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    const auto c = nlohmann::json::parse(line);
    const auto dir =
        scene_dir ? scene_dir->string() : (cases_file.parent_path() / c["scene"].get<std::string>()).string();
    if (!scenes.contains(dir)) scenes.emplace(dir, scene::load_scene(dir));
    nlohmann::json state;
    for (const auto& r : c["rounds"]) state = manager.chat(c["id"], dir, r.get<std::string>()).edit_state;
    manager.reset(c["id"]);
    bool ok = true;
    for (const auto& r : bench::grade_case(scenes.at(dir), state, c["expect"])) ok = ok && r.pass;
    out.passed += ok;
    ++out.total;
    const auto q = bench::motion_quality(scenes.at(dir), state);
    out.vehicles += q.vehicles;
    out.overlapping += q.vehicles - q.no_overlap;
  }
  return out;
}

}  // namespace

// The dev layout's traffic makes two dev requests impossible without driving through a
// recorded vehicle; the planner says so instead (it used to drive through them).
const Exceptions kDevExceptions{
    // Every start in the right front is behind a parked car: it starts nearby, and says so.
    {"add-04", "starts a little further round"},
    // "Make it faster" behind a slower car with both neighbouring lanes busy: it follows.
    {"rev-03", "holds it to"}};

TEST(Commands, DevCasesAllPass) {
  const auto dir = test_support::shared_commands_dir();
  if (!fs::exists(dir / "cases-dev.jsonl")) GTEST_SKIP() << "shared data absent: " << dir;
  run_cases(dir / "cases-dev.jsonl", dir / "scene-layout-dev", kDevExceptions);
}

TEST(Commands, OwnParaphrasesAllPass) {
  const auto dir = test_support::shared_commands_dir();
  if (!fs::exists(dir / "scene-layout-dev")) GTEST_SKIP() << "shared data absent: " << dir;
  run_cases(fs::path(CHATSIM_SOURCE_DIR) / "tests/data/commands-paraphrase.jsonl", dir / "scene-layout-dev",
            {{"p-q12", "holds it to"},                       // faster behind the truck: it follows
             {"p-r19", "no collision-free start matched"}});  // head-on with the car behind the ego
}

// The blind sets (tests/data/commands-blind-v2.jsonl, frozen before the fixes of #41; v3 to v21,
// each frozen after the fixes before it) stay above what they scored when this test was written,
// and no added vehicle ever meets another at any frame.
TEST(Commands, BlindSetsKeepTheirScoreAndNoVehicleMeetsAnother) {
  for (const auto& [file, floor] : {std::pair{"commands-blind-v2.jsonl", 0.94}, std::pair{"commands-blind-v3.jsonl", 0.84},
                                    std::pair{"commands-blind-v4.jsonl", 0.94}, std::pair{"commands-blind-v5.jsonl", 0.96},
                                    std::pair{"commands-blind-v6.jsonl", 0.92}, std::pair{"commands-blind-v7.jsonl", 0.92},
                                    std::pair{"commands-blind-v8.jsonl", 0.92}, std::pair{"commands-blind-v9.jsonl", 0.94},
                                    std::pair{"commands-blind-v10.jsonl", 0.92}, std::pair{"commands-blind-v11.jsonl", 0.94},
                                    std::pair{"commands-blind-v12.jsonl", 0.98}, std::pair{"commands-blind-v13.jsonl", 0.96},
                                    std::pair{"commands-blind-v14.jsonl", 0.92}, std::pair{"commands-blind-v15.jsonl", 0.94},
                                    std::pair{"commands-blind-v16.jsonl", 0.92},
                                    std::pair{"commands-blind-v17.jsonl", 0.94},
                                    std::pair{"commands-blind-v18.jsonl", 0.94},
                                    std::pair{"commands-blind-v19.jsonl", 0.96},
                                    std::pair{"commands-blind-v20.jsonl", 0.96},
                                    std::pair{"commands-blind-v21.jsonl", 0.96},
                                    std::pair{"commands-blind-v23.jsonl", 0.95},
                                    std::pair{"commands-blind-v24.jsonl", 0.9},
                                    std::pair{"commands-blind-v25.jsonl", 0.9},
                                    std::pair{"commands-blind-v26.jsonl", 0.95},
                                    std::pair{"commands-blind-v27.jsonl", 0.95},
                                    std::pair{"commands-blind-v28.jsonl", 0.95},
                                    std::pair{"commands-blind-v29.jsonl", 0.9},
                                    std::pair{"commands-blind-v30.jsonl", 0.9}}) {
    const auto s = score_set(fs::path(CHATSIM_SOURCE_DIR) / "tests/data" / file);
    ASSERT_GE(s.total, 40) << file;
    EXPECT_GE(double(s.passed) / s.total, floor) << file << ": " << s.passed << "/" << s.total;
    EXPECT_EQ(s.overlapping, 0) << file << ": " << s.overlapping << " of " << s.vehicles << " added vehicles meet another";
  }
}

// Blind sets v22 and v23- to v30-nuscenes: commands on a real recording (nuScenes scene-0916 as `chatsim
// scene import nuscenes` writes it), each frozen before its first run (0.53; 0.70; 0.71; 0.60; 0.70; 0.80; 0.70;
// 0.80; 0.80).
TEST(Commands, BlindSetOnARealRecordingKeepsItsScore) {
  const auto data = test_support::shared_commands_dir().parent_path() / "nuscenes-scene-0916";
  if (!fs::exists(data)) GTEST_SKIP() << "shared data absent: " << data;
  import::NuScenesOptions o;
  o.dataroot = data;
  o.lidar = false;
  const auto dir = chatsim::scratch::dir() / ("chatsim-v22-" + std::to_string(::getpid()));
  import::import_nuscenes(o, dir);
  for (const auto& [file, floor, size] : {std::tuple{"commands-blind-v22-nuscenes.jsonl", 0.95, 60},
                                          std::tuple{"commands-blind-v23-nuscenes.jsonl", 0.9, 20},
                                          std::tuple{"commands-blind-v24-nuscenes.jsonl", 0.85, 14},
                                          std::tuple{"commands-blind-v25-nuscenes.jsonl", 0.8, 10},
                                          std::tuple{"commands-blind-v26-nuscenes.jsonl", 0.9, 10},
                                          std::tuple{"commands-blind-v27-nuscenes.jsonl", 0.9, 10},
                                          std::tuple{"commands-blind-v28-nuscenes.jsonl", 0.9, 10},
                                          std::tuple{"commands-blind-v29-nuscenes.jsonl", 0.8, 10},
                                          std::tuple{"commands-blind-v30-nuscenes.jsonl", 0.9, 10}}) {
    const auto s = score_set(fs::path(CHATSIM_SOURCE_DIR) / "tests/data" / file, dir);
    EXPECT_EQ(s.total, size) << file;
    EXPECT_GE(double(s.passed) / s.total, floor) << file << ": " << s.passed << "/" << s.total;
    EXPECT_EQ(s.overlapping, 0) << file << ": " << s.overlapping << " of " << s.vehicles
                                << " added vehicles meet another";
  }
  fs::remove_all(dir);
}

// Multi-round state: references across rounds, put back, and nothing lost after a refusal.
TEST(Commands, ConversationKeepsItsStateAcrossRoundsAndRefusals) {
  const auto dir = test_support::temp_dir_for_scene();
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  agents::manager::Manager manager(agents::local_caller(backend), backend);
  auto s = manager.chat("c", dir, "Delete the red car. Add a blue truck 20 m ahead.").edit_state;
  EXPECT_EQ(s["removed"], nlohmann::json({"parked_red"}));
  ASSERT_EQ(s["added"].size(), 1u);
  s = manager.chat("c", dir, "Add 500 cars in front of me.").edit_state;
  EXPECT_EQ(s["added"].size(), 1u);
  EXPECT_FALSE(s["unresolved"].empty());
  s = manager.chat("c", dir, "Make it red.").edit_state;
  EXPECT_EQ(s["added"][0]["type"], "truck");
  EXPECT_EQ(s["added"][0]["color_rgb"][0].get<int>() > 150, true);
  s = manager.chat("c", dir, "Put back the deleted car.").edit_state;
  EXPECT_TRUE(s["removed"].empty());
  EXPECT_EQ(s["rounds"].size(), 4u);
  manager.reset("c");
  s = manager.chat("c", dir, "Move the view 1 m up.").edit_state;
  EXPECT_TRUE(s["added"].empty());
}

// The same scene moved and turned in the world must give the same decisions: everything is
// read in the ego frame at frame 0.
TEST(Commands, DevCasesPassInARotatedAndShiftedWorld) {
  const auto dir = test_support::shared_commands_dir();
  if (!fs::exists(dir / "cases-dev.jsonl")) GTEST_SKIP() << "shared data absent: " << dir;
  auto s = scene::load_scene(dir / "scene-layout-dev");
  Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
  move.linear() = Eigen::AngleAxisd(0.65, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  move.translation() = Eigen::Vector3d(120, -45, 0);
  for (auto& f : s.frames) f.ego_to_world = move * f.ego_to_world;
  for (auto& o : s.objects)
    for (auto& p : o.track) {
      p.center = move * p.center;
      p.yaw += 0.65;
    }
  std::vector<scene::Lane> lanes = s.lanes.lanes();
  for (auto& l : lanes)
    for (auto& p : l.centerline) p = move * p;
  s.lanes = scene::LaneMap(lanes);
  const auto moved = chatsim::scratch::dir() / ("chatsim-rotated-" + std::to_string(::getpid()));
  scene::save_scene(s, moved);
  run_cases(dir / "cases-dev.jsonl", moved, kDevExceptions);
}

// Without a lane map, decisions still come, and what could not be done is said.
TEST(Commands, NoLaneMapFailsGracefully) {
  auto s = test_support::synthetic_scene(false);
  const auto dir = chatsim::scratch::dir() / ("chatsim-nolanes-" + std::to_string(::getpid()));
  scene::save_scene(s, dir);
  fs::remove(dir / "lanes.json");
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  agents::manager::Manager manager(agents::local_caller(backend), backend);
  const auto state = manager.chat("c", dir, "Add a car 20 m ahead that turns left.").edit_state;
  ASSERT_EQ(state["added"].size(), 1u);
  ASSERT_EQ(state["unresolved"].size(), 1u);
  EXPECT_NE(state["unresolved"][0]["reason"].get<std::string>().find("no lane map"), std::string::npos);
}

// An agent that fails mid-round (e.g. killed) leaves the conversation as it was before the round.
TEST(Commands, AFailedRoundChangesNothing) {
  const auto dir = test_support::temp_dir_for_scene();
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  auto local = agents::local_caller(backend);
  bool motion_down = false;
  agents::manager::Manager manager(
      [&](const std::string& kind, const agents::AgentCall& call) {
        if (kind == "motion" && motion_down)
          return agents::AgentOutcome::failure(agents::ErrorKind::Unavailable, "motion agent did not answer");
        return local(kind, call);
      },
      backend);
  manager.chat("c", dir, "Add a red car 20 m ahead.");
  motion_down = true;
  EXPECT_THROW(manager.chat("c", dir, "Delete the truck and add a bus behind me."), std::runtime_error);
  motion_down = false;
  const auto s = manager.chat("c", dir, "Move the view 1 m up.").edit_state;
  EXPECT_TRUE(s["removed"].empty());       // the failed round's deletion was rolled back
  EXPECT_EQ(s["added"].size(), 1u);
  EXPECT_EQ(s["rounds"].size(), 2u);
}

// The bad-command catalogue: each gets a clear refusal in `unresolved`, nothing crashes, and
// the conversation's earlier rounds are kept.
TEST(Commands, BadCommandsAreRefusedClearlyAndLoseNothing) {
  const auto dir = test_support::temp_dir_for_scene();
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  agents::manager::Manager manager(agents::local_caller(backend), backend);
  auto base = manager.chat("c", dir, "Add a red car 20 m ahead. Move the view 1 m up.").edit_state;
  ASSERT_EQ(base["added"].size(), 1u);
  const std::vector<std::string> bad = {
      "",
      "   ",
      "asdkj qwe zzz",
      std::string(10000, 'x'),
      "Ajoute une voiture rouge devant moi.",
      "添加一辆红色的车",
      "Add 500 cars in front of me.",
      "Delete the purple helicopter.",
      "Make the green truck I added turn left.",
      "Put back the deleted car.",
  };
  for (const auto& command : bad) {
    const auto before = manager.chat("c", dir, "Move the view 0 m up.").edit_state["unresolved"].size();
    const auto s = manager.chat("c", dir, command).edit_state;
    EXPECT_GT(s["unresolved"].size(), before) << "no refusal for: " << command.substr(0, 60);
    EXPECT_EQ(s["added"].size(), 1u) << command.substr(0, 60);
    EXPECT_EQ(s["added"][0]["trajectory"], base["added"][0]["trajectory"]) << command.substr(0, 60);
    EXPECT_DOUBLE_EQ(s["view"]["translation_m"][2].get<double>(), 1.0) << command.substr(0, 60);
  }
}

// "Bring back the black one": of the removed objects, the one described, not the last removal.
TEST(Commands, PutBackWhatTheWordsDescribe) {
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  agents::manager::Manager manager(agents::local_caller(backend), backend);
  const auto dir = (fs::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts/blind-avenue").string();
  auto s = manager.chat("c", dir, "Remove all the parked cars.").edit_state;
  ASSERT_EQ(s["removed"].size(), 4u);  // obj_1, obj_2, obj_3 at the right kerb, obj_12 across the road
  s = manager.chat("c", dir, "Bring back the black one.").edit_state;
  auto removed = s["removed"].get<std::vector<std::string>>();
  std::sort(removed.begin(), removed.end());
  EXPECT_EQ(removed, (std::vector<std::string>{"obj_1", "obj_12", "obj_2"}));
  s = manager.chat("c", dir, "Put them back.").edit_state;  // nothing described: the rest of that removal
  EXPECT_TRUE(s["removed"].empty());
}

// "The ego drives slowly", then "a truck ahead at the same speed": the speed the view gives the ego.
TEST(Commands, TheSameSpeedAsTheEgoFollowsTheViewsEgoMotion) {
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  agents::manager::Manager manager(agents::local_caller(backend), backend);
  const auto dir = (fs::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts/blind-oneway").string();
  manager.chat("c", dir, "The ego car should drive slowly.");
  const auto s = manager.chat("c", dir, "Add a truck ahead of me driving at the same speed.").edit_state;
  ASSERT_EQ(s["added"].size(), 1u);
  EXPECT_NEAR(s["added"][0]["intent"]["speed_mps"].get<double>(), 3.0, 0.01);  // view::ego_speed_mps("slow")
}
