// chatsim serve in headless Chromium: a user types a command on the page, the round is rendered
// through every process, the page shows the answer and a rendered frame (checked on the
// screenshot), and Ctrl-C leaves no process behind.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::ScopedProcess;
namespace fs = std::filesystem;

namespace {

std::string capture(const std::string& cmd, int* status) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  *status = pclose(p);
  return out;
}

// playwright-core, installed once into the build tree; empty when node, npm or Chromium are missing.
fs::path web_js_dir() {
  const fs::path dir = fs::path(CHATSIM_BIN_DIR) / ".." / "web-js";
  if (!fs::exists("/usr/bin/chromium")) return {};
  if (fs::exists(dir / "node_modules" / "playwright-core")) return dir;
  if (std::system("command -v node >/dev/null && command -v npm >/dev/null") != 0) return {};
  fs::create_directories(dir);
  int status = 0;
  capture("cd " + dir.string() + " && timeout 300 npm install --silent --no-audit --no-fund playwright-core@1.49.1 2>&1", &status);
  return status == 0 ? dir : fs::path();
}

}  // namespace

TEST(Serve, ChatPageRendersARoundInHeadlessChromium) {
  const fs::path js = web_js_dir();
  if (js.empty()) GTEST_SKIP() << "Chromium (/usr/bin/chromium), node or npm not available: the page test did not run";
  const fs::path root = test_support::temp_path("serve-test");
  fs::remove_all(root);
  fs::create_directories(root);
  int status = 0;
  capture(bin("chatsim") + " scene demo --out " + (root / "scene").string() +
              " --preset small --frames 3 --no-plates --no-views --seed 4 2>&1", &status);
  ASSERT_EQ(status, 0);
  const fs::path port_file = root / "port";
  ScopedProcess server(test_support::spawn(
      {"/usr/bin/env", "CHATSIM_CACHE=" + (root / "cache").string(), "CHATSIM_TRAIN_ITERATIONS=40", bin("chatsim"), "serve",
       "--scene", (root / "scene").string(), "--port", "0", "--port-file", port_file.string(), "--out-root",
       (root / "out").string()},
      (root / "serve.log").string()));
  for (int i = 0; i < 300 && !fs::exists(port_file); ++i) std::this_thread::sleep_for(100ms);
  ASSERT_TRUE(fs::exists(port_file)) << test_support::read_file(root / "serve.log");
  const int port = std::stoi(test_support::read_file(port_file));
  const fs::path shot = root / "page.png";
  // ES modules resolve packages beside the script: run a copy from where playwright-core is.
  fs::copy_file(fs::path(CHATSIM_SOURCE_DIR) / "tests" / "web" / "chat_page.mjs", js / "chat_page.mjs",
                fs::copy_options::overwrite_existing);
  const std::string out = capture("cd " + js.string() + " && timeout 400 node chat_page.mjs"
                                      " http://127.0.0.1:" + std::to_string(port) + "/ " + shot.string() +
                                      " 'Add a red car 12 m ahead' 2>&1",
                                  &status);
  ASSERT_EQ(status, 0) << out << "\n" << test_support::read_file(root / "serve.log");
  const auto result = nlohmann::json::parse(out.substr(out.find('{')));
  EXPECT_FALSE(result["failed"].get<bool>()) << result["log"];
  EXPECT_NE(result["log"].get<std::string>().find("Added"), std::string::npos) << result["log"];
  EXPECT_GT(result["frame"]["width"].get<int>(), 0);
  // The screenshot shows the rendered frame: the image's area is a picture, not a blank.
  const cv::Mat png = cv::imread(shot.string());
  ASSERT_FALSE(png.empty());
  const auto& box = result["frame"]["box"];
  const cv::Rect r(int(box["x"].get<double>()), int(box["y"].get<double>()), int(box["width"].get<double>()),
                   int(box["height"].get<double>()));
  ASSERT_GT(r.area(), 1000);
  cv::Scalar mean, stddev;
  cv::meanStdDev(png(r & cv::Rect(0, 0, png.cols, png.rows)), mean, stddev);
  EXPECT_GT(stddev[0] + stddev[1] + stddev[2], 20) << "the frame area looks blank";
  // Ctrl-C: the server, its agents and the bus all stop.
  kill(server.pid, SIGINT);
  const auto st = server.wait(15s);
  ASSERT_TRUE(st);
  EXPECT_TRUE(WIFEXITED(*st) && WEXITSTATUS(*st) == 0);
  std::this_thread::sleep_for(500ms);
  for (const char* name : {"chatsim-manager", "chatsim-backgro", "chatsim-bus"})  // comm is cut at 15 characters
    EXPECT_EQ(test_support::count_with_env(name, (root / "cache").string()), 0) << name;
  fs::remove_all(root);
}
