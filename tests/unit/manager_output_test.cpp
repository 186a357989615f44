// The manager checks a rendered round's folder before the round changes the conversation: a
// folder it may not write costs the user nothing, whoever asked (chat, serve, a bus client).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "agents/core/agent_registry.hpp"
#include "agents/manager/manager.hpp"
#include "common/util/output_dir.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim;
namespace fs = std::filesystem;

namespace {

struct Rendered {
  int calls = 0;
  bool force = false;
};

std::unique_ptr<agents::Agent> manager_with(Rendered& rendered) {
  std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend("offline");
  return agents::manager::make_manager_agent(
      agents::local_caller(backend), backend,
      [&rendered](const std::string&, const nlohmann::json&, const std::string& out, const std::string&, bool force) {
        ++rendered.calls, rendered.force = force;
        return agents::AgentOutcome::success({{"output_dir", out}});
      });
}

agents::AgentCall round(const std::string& scene, const std::string& command, const fs::path& out, bool force = false) {
  return {"chat", scene,
          {{"command", command}, {"conversation_id", "c"}, {"render", !out.empty()}, {"output_dir", out.string()},
           {"force_output", force}}};
}

TEST(ManagerOutput, AFolderItMayNotWriteFailsTheRoundBeforeAnythingIsDecided) {
  const std::string scene = test_support::temp_dir_for_scene();
  const fs::path users = scratch::dir() / "manager-output-users";
  fs::create_directories(users);
  std::ofstream(users / "thesis.txt") << "years of work";
  Rendered rendered;
  auto manager = manager_with(rendered);
  const auto refused = manager->handle(round(scene, "Add a red car 20 m ahead.", users, true));
  ASSERT_FALSE(refused.ok);
  EXPECT_EQ(refused.error, agents::ErrorKind::BadRequest);
  EXPECT_NE(refused.message.find(users.string()), std::string::npos) << refused.message;
  EXPECT_EQ(rendered.calls, 0);
  EXPECT_TRUE(fs::exists(users / "thesis.txt"));
  // The refused round left no trace: the next round is the conversation's first.
  const auto next = manager->handle(round(scene, "Add a blue car 30 m ahead.", ""));
  ASSERT_TRUE(next.ok) << next.message;
  EXPECT_EQ(next.result["edit_state"]["rounds"].size(), 1u);
  EXPECT_EQ(next.result["edit_state"]["added"].size(), 1u);
}

TEST(ManagerOutput, TheSceneItselfIsNeverTheOutputAndForceReachesTheRenderer) {
  const std::string scene = test_support::temp_dir_for_scene();
  Rendered rendered;
  auto manager = manager_with(rendered);
  EXPECT_FALSE(manager->handle(round(scene, "Add a red car 20 m ahead.", scene, true)).ok);
  EXPECT_FALSE(manager->handle(round(scene, "Add a red car 20 m ahead.", fs::path(scene).parent_path(), true)).ok);
  EXPECT_TRUE(fs::exists(fs::path(scene) / "scene.json"));
  EXPECT_EQ(rendered.calls, 0);
  const auto ok = manager->handle(round(scene, "Add a red car 20 m ahead.", scratch::dir() / "manager-output-new", true));
  ASSERT_TRUE(ok.ok) << ok.message;
  EXPECT_EQ(rendered.calls, 1);
  EXPECT_TRUE(rendered.force);
}

}  // namespace
