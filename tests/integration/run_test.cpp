// chatsim run through all eight processes on a small rendered demo scene: the result folder has
// every frame, the video, labels without the removed object and with the added one, and a second
// run reuses the cached radiance field and background stage. No process is left behind.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
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
  // Again, one more round of the same edit: training and background come from the cache.
  const fs::path out2 = *root_ / "result2";
  const std::string cmd2 = env() + bin("chatsim") + " run --scene " + (*root_ / "scene").string() + " --out " + out2.string() +
                           " 'Remove the nearest car and add a red car 15 m ahead' 'Make it blue.' > " +
                           (*root_ / "run2.log").string() + " 2>&1";
  ASSERT_EQ(run_shell(cmd2, 300s), 0) << test_support::read_file(*root_ / "run2.log");
  const auto second = nlohmann::json::parse(test_support::read_file(out2 / "result.json"));
  EXPECT_TRUE(second["reused"]["training"].get<bool>());
  EXPECT_TRUE(second["reused"]["background"].get<bool>());
  EXPECT_TRUE(second["reused"]["deletion"].get<bool>());
  EXPECT_FALSE(second["reused"]["foreground"].get<bool>());  // the car changed colour
  for (const char* name : {"chatsim-manager", "chatsim-foregro", "chatsim-bus"})  // comm is cut at 15 characters
    EXPECT_EQ(test_support::count_with_env(name, (*root_ / "cache").string()), 0) << name;
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
