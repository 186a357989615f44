// chatsim plan through real processes: it starts the bus and the decision agents when no bus
// runs, answers over the bus, prints the edit state, and leaves no process behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::ScopedProcess;
namespace fs = std::filesystem;

namespace {

fs::path layout_scene() {
  return fs::path(CHATSIM_SOURCE_DIR) / ".." / "shared" / "data" / "commands" / "scene-layout-dev";
}

}  // namespace

TEST(Plan, TwoRoundsThroughTheBusPrintTheEditState) {
  if (!fs::exists(layout_scene())) GTEST_SKIP() << "shared data absent: " << layout_scene();
  const auto out = test_support::temp_path("plan-out.json");
  ScopedProcess proc(test_support::spawn(
      {"/bin/sh", "-c",
       bin("chatsim") + " plan --scene " + layout_scene().string() +
           " 'Remove all cars and add a red Porsche 20 m ahead driving toward me fast.' 'Make it blue.' > " +
           out.string() + " 2>/dev/null"},
      "/dev/null"));
  const auto status = proc.wait(60s);
  ASSERT_TRUE(status);
  ASSERT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0);
  const auto state = nlohmann::json::parse(test_support::read_file(out));
  EXPECT_EQ(state["scene"], "layout-dev");
  EXPECT_EQ(state["removed"].size(), 8u);
  ASSERT_EQ(state["added"].size(), 1u);
  EXPECT_EQ(state["added"][0]["asset"], "porsche_911");
  EXPECT_LT(state["added"][0]["color_rgb"][0].get<int>(), 100);  // blue now
  // Fast toward the ego, it drives off the mapped lanes before the clip ends and leaves the scene there.
  const auto& trajectory = state["added"][0]["trajectory"];
  EXPECT_GT(trajectory.size(), 20u);
  EXPECT_LE(trajectory.size(), 100u);
  EXPECT_FALSE(state["notes"].empty());
  EXPECT_EQ(state["rounds"].size(), 2u);
  EXPECT_EQ(test_support::count_children("chatsim-motion"), 0);
}

TEST(Plan, BadSceneIsAUsageErrorNamingTheFile) {
  const auto log = test_support::temp_path("plan-bad.log");
  ScopedProcess proc(test_support::spawn({bin("chatsim"), "plan", "--scene", "/nonexistent/scene", "add a car"}, log));
  const auto status = proc.wait(20s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 2);
  EXPECT_NE(test_support::read_file(log).find("/nonexistent/scene"), std::string::npos);
}

TEST(Plan, SceneInfoSummarises) {
  if (!fs::exists(layout_scene())) GTEST_SKIP() << "shared data absent: " << layout_scene();
  const auto log = test_support::temp_path("scene-info.log");
  ScopedProcess proc(test_support::spawn({bin("chatsim"), "scene", "info", layout_scene().string()}, log));
  const auto status = proc.wait(20s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 0);
  const auto text = test_support::read_file(log);
  EXPECT_NE(text.find("frames: 100"), std::string::npos) << text;
  EXPECT_NE(text.find("vehicle.car: 6"), std::string::npos) << text;
}

// eval commands reports each category's slowest round and every round over #41's targets; with
// --repeat, each round timed by its median over the runs, and the same grades.
TEST(Plan, EvalCommandsReportsTheSlowestRoundAndRoundsOverTheTargets) {
  const auto cases = fs::path(CHATSIM_SOURCE_DIR) / "tests/data/commands-blind-v15.jsonl";
  const auto two = test_support::temp_path("two-cases.jsonl");
  {
    std::ifstream in(cases);
    std::ofstream o(two);
    std::string line;
    for (int k = 0; k < 2 && std::getline(in, line); ++k) {
      auto j = nlohmann::json::parse(line);
      j["scene"] = (cases.parent_path() / j["scene"].get<std::string>()).string();  // the copy lives elsewhere
      o << j.dump() << "\n";
    }
  }
  const auto eval = [&](const std::string& extra) {
    const auto out = test_support::temp_path("eval-out.json");
    ScopedProcess proc(test_support::spawn({"/bin/sh", "-c", bin("chatsim") + " eval commands --cases " + two.string() +
                                                                 extra + " > " + out.string() + " 2>/dev/null"},
                                           "/dev/null"));
    const auto status = proc.wait(60s);
    EXPECT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << extra;
    return nlohmann::json::parse(test_support::read_file(out));
  };
  const auto report = eval("");
  EXPECT_EQ(report["cases"], 2);
  EXPECT_EQ(report["timed_by"], "one run");
  const auto repeated = eval(" --repeat 3");
  EXPECT_EQ(repeated["timed_by"], "median of 3 runs per round");
  EXPECT_EQ(repeated["passed"], report["passed"]);
  EXPECT_EQ(repeated["failures"], report["failures"]);
  for (const auto& [name, category] : report["by_category"].items()) {
    EXPECT_GE(category["max_decision_latency_ms"].get<double>(), category["mean_decision_latency_ms"].get<double>()) << name;
  }
  ASSERT_TRUE(report["slow_rounds"].is_array());
  for (const auto& r : report["slow_rounds"]) EXPECT_GT(r["ms"].get<double>(), r["target_ms"].get<double>());
}
