// chatsim run through all eight processes on a small rendered demo scene: the result folder has
// every frame, the video, labels without the removed object and with the added one, and a second
// run reuses the cached radiance field and background stage. No process is left behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "common/util/output_dir.hpp"
#include "tests/support/bus_fixture.hpp"
#include "tests/support/heartbeat_watcher.hpp"
#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::HeartbeatWatcher;
using test_support::ScopedProcess;
namespace fs = std::filesystem;

namespace {

int run_shell(const std::string& cmd, std::chrono::seconds timeout) {
  ScopedProcess proc(test_support::spawn({"/bin/sh", "-c", cmd}, "/dev/null"));
  const auto status = proc.wait(timeout);
  if (!status) return -1;
  return WIFEXITED(*status) ? WEXITSTATUS(*status) : -2;
}

class Run : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(test_support::temp_path("run-test"));
    fs::create_directories(*root_);
    // 4 frames of 160 x 106: rendering and training stay within seconds.
    ASSERT_EQ(run_shell(bin("chatsim") + " scene demo --out " + (*root_ / "scene").string() +
                            " --preset small --frames 4 --no-plates --no-views --seed 2 > /dev/null 2>&1",
                        120s),
              0);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*root_);
    delete root_;
  }
  static std::string env() {
    return "CHATSIM_CACHE=" + (*root_ / "cache").string() + " CHATSIM_TRAIN_ITERATIONS=60 ";
  }
  static fs::path* root_;
};
fs::path* Run::root_ = nullptr;

TEST_F(Run, RemovesAddsAndWritesEveryOutputThenReusesStages) {
  const fs::path out = *root_ / "result";
  const std::string cmd = env() + bin("chatsim") + " run --scene " + (*root_ / "scene").string() + " --out " + out.string() +
                          " 'Remove the nearest car and add a red car 15 m ahead' > " + (*root_ / "run.log").string() + " 2>&1";
  ASSERT_EQ(run_shell(cmd, 300s), 0) << test_support::read_file(*root_ / "run.log");
  for (const char* f : {"video.mp4", "edit.json", "result.json", "labels/labels.json", "labels/kitti/front/000000.txt",
                        "frames/front/000003.png", "frames/front_left/000000.png", "depth/front/000000.exr"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_GT(fs::file_size(out / "video.mp4"), 1000u);
  const auto edit = nlohmann::json::parse(test_support::read_file(out / "edit.json"));
  ASSERT_EQ(edit["removed"].size(), 1u);
  ASSERT_EQ(edit["added"].size(), 1u);
  const std::string removed = edit["removed"][0];
  const auto labels = nlohmann::json::parse(test_support::read_file(out / "labels" / "labels.json"));
  ASSERT_EQ(labels["frames"].size(), 4u);
  bool added_seen = false;
  for (const auto& f : labels["frames"])
    for (const auto& o : f["objects"]) {
      EXPECT_NE(o["id"], removed) << "a removed object is still labelled";
      if (o["source"] == "added" && o["cameras"].contains("front")) added_seen = true;
    }
  EXPECT_TRUE(added_seen) << "the added car should be labelled in the front camera";
  // The added car's pixels differ from the captured image (it is drawn), the rest mostly not.
  const auto first = nlohmann::json::parse(test_support::read_file(out / "result.json"));
  EXPECT_FALSE(first["reused"]["background"].get<bool>());
  EXPECT_FALSE(first["reused"]["light"].get<bool>());  // estimated once, ahead of the stages
  EXPECT_EQ(output_kind(out), "result");
  // Again, one more round of the same edit, into the same folder (chatsim's own: replaced):
  // training and background come from the cache.
  const fs::path out2 = out;
  const std::string cmd2 = env() + bin("chatsim") + " run --scene " + (*root_ / "scene").string() + " --out " + out2.string() +
                           " 'Remove the nearest car and add a red car 15 m ahead' 'Make it blue.' > " +
                           (*root_ / "run2.log").string() + " 2>&1";
  ASSERT_EQ(run_shell(cmd2, 300s), 0) << test_support::read_file(*root_ / "run2.log");
  const auto second = nlohmann::json::parse(test_support::read_file(out2 / "result.json"));
  EXPECT_EQ(nlohmann::json::parse(test_support::read_file(out2 / "edit.json"))["rounds"].size(), 2u);  // the new result
  EXPECT_TRUE(second["reused"]["training"].get<bool>());
  EXPECT_TRUE(second["reused"]["light"].get<bool>());
  EXPECT_TRUE(second["reused"]["background"].get<bool>());
  EXPECT_TRUE(second["reused"]["deletion"].get<bool>());
  EXPECT_FALSE(second["reused"]["foreground"].get<bool>());  // the car changed colour
  for (const char* name : {"chatsim-manager", "chatsim-foregro", "chatsim-bus"})  // comm is cut at 15 characters
    EXPECT_EQ(test_support::count_with_env(name, (*root_ / "cache").string()), 0) << name;
}

// Each rendering agent killed with -9 while it works on a rendered round: chatsim run says
// which agent failed within 5 s and leaves no result folder, not even a half-written one; with
// the agent back, the same round succeeds.
TEST_F(Run, ARenderingAgentKilledMidRenderIsReportedAndLeavesNoOutput) {
  setenv("CHATSIM_TRAIN_ITERATIONS", "60", 1);
  setenv("CHATSIM_FOREGROUND_SPP", "4", 1);
  for (const std::string victim : {"background", "deletion", "foreground"}) {
    SCOPED_TRACE(victim);
    // A cache of its own: stages an earlier victim's run rendered would be reused, not asked for.
    setenv("CHATSIM_CACHE", (*root_ / ("cache-" + victim)).c_str(), 1);
    test_support::InProcessBus b;
    bus::Node client(b.options("client"), b.context());
    HeartbeatWatcher watcher(client);
    double asked_at = 0;
    client.subscribe(bus::topics::agent_request(victim), [&](const bus::Message&) {
      if (asked_at == 0) asked_at = mono_s();
    });
    client.start();
    std::vector<std::unique_ptr<ScopedProcess>> agents;
    for (const std::string kind : {"manager", "view", "background", "deletion", "asset", "motion", "foreground"}) {
      if (kind == victim) continue;
      agents.push_back(std::make_unique<ScopedProcess>(test_support::spawn({bin("chatsim-" + kind), "--bus", b.endpoint()}, "/dev/null")));
      ASSERT_TRUE(watcher.wait_for(kind, 10s)) << kind;
    }
    const fs::path script = *root_ / ("slow-" + victim + ".yaml");
    std::ofstream(script) << "agent: " << victim << "\nresponses:\n  - delay_ms: 30000\n    result: {}\n";
    auto slow = std::make_unique<ScopedProcess>(
        test_support::spawn({bin("chatsim-mock"), "--script", script.string(), "--bus", b.endpoint()}, "/dev/null"));
    ASSERT_TRUE(watcher.wait_for(victim, slow->pid, 5s));

    const fs::path out = *root_ / ("killed-" + victim);
    const fs::path log = *root_ / ("killed-" + victim + ".log");
    const std::vector<std::string> run = {bin("chatsim"), "run", "--bus", b.endpoint(), "--scene", (*root_ / "scene").string(),
                                          "--out", out.string(), "Remove the nearest car and add a red car 15 m ahead"};
    ScopedProcess round(test_support::spawn(run, log.string()));
    // Killed once the request has reached it (earlier stages take seconds: training, renders).
    const double until = mono_s() + 120;
    while (asked_at == 0 && mono_s() < until) client.spin_once(20ms);
    ASSERT_GT(asked_at, 0) << "the " << victim << " agent was never asked: " << test_support::read_file(log);
    std::this_thread::sleep_for(300ms);
    const double killed_at = mono_s();
    kill(slow->pid, SIGKILL);
    const auto status = round.wait(20s);
    ASSERT_TRUE(status) << "chatsim run did not notice";
    EXPECT_LT(mono_s() - killed_at, 5.0);
    EXPECT_NE(WEXITSTATUS(*status), 0);
    EXPECT_NE(test_support::read_file(log).find("the " + victim + " agent failed"), std::string::npos) << test_support::read_file(log);
    EXPECT_FALSE(fs::exists(out));
    for (const auto& e : fs::directory_iterator(*root_))
      EXPECT_EQ(e.path().filename().string().find("killed-" + victim + ".part"), std::string::npos) << e.path();

    // Back (as the launcher respawns it): the same round succeeds.
    slow.reset();
    agents.push_back(std::make_unique<ScopedProcess>(test_support::spawn({bin("chatsim-" + victim), "--bus", b.endpoint()}, "/dev/null")));
    ASSERT_TRUE(watcher.wait_for(victim, agents.back()->pid, 10s));
    ScopedProcess again(test_support::spawn(run, log.string()));
    const auto ok = again.wait(240s);
    ASSERT_TRUE(ok);
    EXPECT_EQ(WEXITSTATUS(*ok), 0) << test_support::read_file(log);
    EXPECT_TRUE(fs::exists(out / "video.mp4"));
  }
  unsetenv("CHATSIM_CACHE");
  unsetenv("CHATSIM_TRAIN_ITERATIONS");
  unsetenv("CHATSIM_FOREGROUND_SPP");
}

// A scene whose image is corrupt (it exists, so the scene loads) fails the round with a message
// naming the file, and leaves no result folder.
TEST_F(Run, ACorruptImageFailsTheRoundNamingItAndLeavesNoOutput) {
  const fs::path scene = *root_ / "corrupt-scene";
  fs::copy(*root_ / "scene", scene, fs::copy_options::recursive);
  std::vector<fs::path> images;
  for (const auto& e : fs::recursive_directory_iterator(scene / "images"))
    if (e.is_regular_file()) images.push_back(e.path());
  ASSERT_FALSE(images.empty());
  std::sort(images.begin(), images.end());
  std::ofstream(images.front(), std::ios::trunc) << "not an image";
  const fs::path out = *root_ / "corrupt-out", log = *root_ / "corrupt.log";
  const int code = run_shell("CHATSIM_CACHE=" + (*root_ / "cache-corrupt").string() + " CHATSIM_TRAIN_ITERATIONS=60 " +
                                 bin("chatsim") + " run --scene " + scene.string() + " --out " + out.string() +
                                 " 'Remove the nearest car' > " + log.string() + " 2>&1",
                             120s);
  const std::string said = test_support::read_file(log);
  EXPECT_GT(code, 0) << said;
  EXPECT_NE(said.find(images.front().filename().string()), std::string::npos) << said;
  EXPECT_NE(said.find("corrupt"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Run, LayoutOnlySceneIsRefusedBeforeAnyProcessStarts) {
  const fs::path layout = *root_ / "layout";
  ASSERT_EQ(run_shell(bin("chatsim") + " scene demo --layout-only --out " + layout.string() + " > /dev/null 2>&1", 60s), 0);
  EXPECT_EQ(run_shell(bin("chatsim") + " run --scene " + layout.string() + " --out " + (*root_ / "x").string() +
                          " 'Add a car' > /dev/null 2>&1",
                      60s),
            2);
  EXPECT_FALSE(fs::exists(*root_ / "x"));
}

}  // namespace
