// The decision pipeline end to end (in-process) on graded command cases: the shared dev cases
// and our own paraphrases (tests/data), which guard against fitting the dev phrasing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "agents/core/agent_registry.hpp"
#include "bench/command_grader.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim;
namespace fs = std::filesystem;

namespace {

void run_cases(const fs::path& cases_file, const fs::path& scene_dir) {
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
    for (const auto& r : bench::grade_case(scene, state, c["expect"]))
      EXPECT_TRUE(r.pass) << c["id"].get<std::string>() << ": " << r.check << ": " << r.detail;
    ++n;
  }
  EXPECT_GT(n, 20);
}

}  // namespace

TEST(Commands, DevCasesAllPass) {
  const auto dir = test_support::shared_commands_dir();
  if (!fs::exists(dir / "cases-dev.jsonl")) GTEST_SKIP() << "shared data absent: " << dir;
  run_cases(dir / "cases-dev.jsonl", dir / "scene-layout-dev");
}

TEST(Commands, OwnParaphrasesAllPass) {
  const auto dir = test_support::shared_commands_dir();
  if (!fs::exists(dir / "scene-layout-dev")) GTEST_SKIP() << "shared data absent: " << dir;
  run_cases(fs::path(CHATSIM_SOURCE_DIR) / "tests/data/commands-paraphrase.jsonl", dir / "scene-layout-dev");
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
