// chatsim bag: record a live bus to MCAP, read it back with the independent npm @mcap reader
// (CRCs validated), play it into a bus, and replay a recorded command into a fresh pipeline.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "common/bag/mcap_reader.hpp"
#include "common/bus/topics.hpp"
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

std::string run_capture(const std::string& cmd, int* status = nullptr) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int rc = pclose(p);
  if (status) *status = rc;
  return out;
}

// `chatsim plan`'s edit state (its stdout); when there is none, the failure shows what plan said.
nlohmann::json plan_edit_state(const std::string& plan_command) {
  const auto log = test_support::temp_path("plan.log");
  int status = 0;
  const std::string out = run_capture(plan_command + " 2>" + log.string(), &status);
  const auto said = test_support::read_file(log);
  const auto j = nlohmann::json::parse(out, nullptr, false);
  EXPECT_EQ(status, 0) << said;
  EXPECT_FALSE(j.is_discarded()) << "plan printed no edit state: " << said;
  return j;
}

// The npm reader, installed once into the build tree. Empty when node or npm cannot be had.
fs::path mcap_js_dir() {
  const fs::path dir = fs::path(CHATSIM_BIN_DIR) / ".." / "mcap-js";
  if (fs::exists(dir / "node_modules" / "@mcap" / "core") && fs::exists(dir / "node_modules" / "fzstd")) return dir;
  if (std::system("command -v node >/dev/null && command -v npm >/dev/null") != 0) return {};
  fs::create_directories(dir);
  int status = 0;
  run_capture("cd " + dir.string() + " && timeout 300 npm install --silent --no-audit --no-fund @mcap/core@2.2.2 "
              "@mcap/nodejs@1.0.2 fzstd@0.1.1 2>&1",
              &status);
  return status == 0 ? dir : fs::path();
}

// Ends a recording the way a user does (Ctrl-C), once the run it records is over, rather than
// after a fixed duration that a slow machine can outlast.
void stop_recording(ScopedProcess& recorder) {
  std::this_thread::sleep_for(300ms);  // the last answers are still on their way to the recorder
  kill(recorder.pid, SIGINT);
  const auto status = recorder.wait(10s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 0);
}

}  // namespace

TEST(Bag, RecordValidatesWithTheNpmReaderAndPlaysBack) {
  test_support::InProcessBus b;
  const auto file = test_support::temp_path("record.mcap");
  fs::remove(file);
  ScopedProcess recorder(test_support::spawn(
      {bin("chatsim"), "bag", "record", "--all", "-o", file.string(), "--duration-s", "4", "--bus", b.endpoint()},
      test_support::temp_path("record.log").string()));
  bus::Node pub(b.options("publisher", 100), b.context());
  HeartbeatWatcher watcher(pub);
  pub.start();
  ASSERT_TRUE(watcher.wait_for("bag-record-" + std::to_string(recorder.pid), 5s));
  for (int i = 0; i < 200; ++i) {
    flatbuffers::FlatBufferBuilder fbb;
    const auto req = msgs::CreateAgentRequestDirect(fbb, "motion", "plan", "", ("{\"i\":" + std::to_string(i) + "}").c_str());
    ASSERT_EQ(pub.publish("/test/a", fbb, msgs::Payload::AgentRequest, req.Union()), bus::PublishStatus::Sent);
  }
  std::vector<uchar> jpeg;
  cv::imencode(".jpg", cv::Mat(48, 64, CV_8UC3, cv::Scalar(30, 120, 200)), jpeg);
  for (int i = 0; i < 5; ++i) {
    flatbuffers::FlatBufferBuilder fbb;
    const auto data = fbb.CreateVector(jpeg);
    const auto img = msgs::CreateImage(fbb, fbb.CreateString("front"), i, 0.1 * i, 64, 48, 0, msgs::ImageEncoding::Jpeg, data);
    ASSERT_EQ(pub.publish("/camera/front", fbb, msgs::Payload::Image, img.Union()), bus::PublishStatus::Sent);
  }
  const auto status = recorder.wait(15s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 0) << test_support::read_file(test_support::temp_path("record.log"));
  ASSERT_TRUE(fs::exists(file));
  EXPECT_FALSE(fs::exists(file.string() + ".part"));

  const bag::McapReader reader(file);
  uint64_t a = 0, img = 0, foxglove = 0;
  for (const auto& [id, n] : reader.summary().channel_counts) {
    const auto& topic = reader.summary().channels.at(id).topic;
    if (topic == "/test/a") a = n;
    if (topic == "/camera/front") img = n;
    if (topic == "/camera/front/foxglove") foxglove = n;
  }
  EXPECT_EQ(a, 200u);
  EXPECT_EQ(img, 5u);
  EXPECT_EQ(foxglove, 5u);
  EXPECT_EQ(reader.summary().metadata.at("chatsim.recording").at("lost"), "0");

  const auto js = mcap_js_dir();
  if (js.empty()) {
    ADD_FAILURE() << "node/npm or the npm packages are not available: the independent MCAP check did not run";
  } else {
    // ES modules resolve packages from the script's folder: run a copy placed beside them.
    fs::copy_file(fs::path(CHATSIM_SOURCE_DIR) / "tests/mcap/read_mcap.mjs", js / "read_mcap.mjs",
                  fs::copy_options::overwrite_existing);
    int rc = 0;
    const auto out = run_capture("cd " + js.string() + " && node read_mcap.mjs " + file.string() + " 2>&1", &rc);
    ASSERT_EQ(rc, 0) << out;
    const auto j = nlohmann::json::parse(out);
    EXPECT_EQ(j["count"].get<uint64_t>(), reader.summary().message_count);
    EXPECT_EQ(j["statistics_count"].get<uint64_t>(), reader.summary().message_count);
    EXPECT_EQ(j["topics"]["/test/a"], 200);
    EXPECT_EQ(j["topics"]["/camera/front/foxglove"], 5);
    EXPECT_EQ(j["metadata"]["chatsim.recording"]["lost"], "0");
  }

  // Play /test/a back as fast as possible: all 200, in their original order.
  bus::Node sub(b.options("subscriber"), b.context());
  std::vector<uint64_t> seqs;
  sub.subscribe("/test/a", [&](const bus::Message& m) { seqs.push_back(m.header().seq()); });
  sub.start();
  ScopedProcess player(test_support::spawn(
      {bin("chatsim"), "bag", "play", file.string(), "--rate", "0", "--topics", "/test/a", "--bus", b.endpoint()}, "/dev/null"));
  const auto end = std::chrono::steady_clock::now() + 15s;
  while (seqs.size() < 200 && std::chrono::steady_clock::now() < end) sub.spin_once(20ms);
  ASSERT_EQ(seqs.size(), 200u);
  EXPECT_TRUE(std::is_sorted(seqs.begin(), seqs.end()));
  const auto played = player.wait(10s);
  ASSERT_TRUE(played);
  EXPECT_EQ(WEXITSTATUS(*played), 0);
}

// Replaying a recorded command into a fresh pipeline gives the same edit state.
TEST(Bag, ReplayingACommandGivesTheSameEditState) {
  const fs::path scene = fs::path(CHATSIM_SOURCE_DIR) / ".." / "shared" / "data" / "commands" / "scene-layout-dev";
  if (!fs::exists(scene)) GTEST_SKIP() << "shared data absent: " << scene;
  test_support::InProcessBus b;
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  std::map<std::string, std::unique_ptr<ScopedProcess>> agents;
  auto start_agent = [&](const std::string& kind) {
    agents[kind] = std::make_unique<ScopedProcess>(test_support::spawn({bin("chatsim-" + kind), "--bus", b.endpoint()}, "/dev/null"));
    return watcher.wait_for(kind, agents[kind]->pid, 5s);
  };
  for (const std::string kind : {"manager", "view", "deletion", "asset", "motion"}) ASSERT_TRUE(start_agent(kind)) << kind;

  const auto file = test_support::temp_path("replay.mcap");
  fs::remove(file);
  ScopedProcess recorder(test_support::spawn(
      {bin("chatsim"), "bag", "record", "/chat/request", "-o", file.string(), "--bus", b.endpoint()}, "/dev/null"));
  ASSERT_TRUE(watcher.wait_for("bag-record-" + std::to_string(recorder.pid), 5s));
  const auto expected = plan_edit_state(bin("chatsim") + " plan --bus " + b.endpoint() + " --scene " + scene.string() +
                                        " 'Remove the red car and add a police car 20 m ahead driving toward me.'"
                                        " 'Make it turn left.'");
  stop_recording(recorder);

  // A fresh manager: no memory of the conversation.
  agents["manager"].reset();
  ASSERT_TRUE(start_agent("manager"));
  const bag::McapReader reader(file);
  ASSERT_EQ(reader.summary().message_count, 2u);
  std::string reply_topic;
  reader.for_each([&](const bag::McapMessage& m) {
    reply_topic = std::string(bus::view(msgs::GetEnvelope(m.data.data())->header()->reply_to()));
  });
  ASSERT_FALSE(reply_topic.empty());
  std::vector<std::string> edits;
  client.subscribe(reply_topic, [&](const bus::Message& m) {
    if (const auto* r = m.payload<msgs::ChatResponse>()) edits.emplace_back(bus::view(r->edit_state_json()));
  });
  client.sync();
  ScopedProcess player(test_support::spawn({bin("chatsim"), "bag", "play", file.string(), "--bus", b.endpoint()}, "/dev/null"));
  const auto end = std::chrono::steady_clock::now() + 20s;
  while (edits.size() < 2 && std::chrono::steady_clock::now() < end) client.spin_once(20ms);
  ASSERT_EQ(edits.size(), 2u);
  EXPECT_EQ(nlohmann::json::parse(edits.back()), expected);
}

// A recorded agent answers a later run in its place: the pipeline is replayed with
// chatsim-mock --bag standing in for the motion agent, and decides the same.
TEST(Bag, ARecordedAgentAnswersALaterRun) {
  const fs::path scene = fs::path(CHATSIM_SOURCE_DIR) / ".." / "shared" / "data" / "commands" / "scene-layout-dev";
  if (!fs::exists(scene)) GTEST_SKIP() << "shared data absent: " << scene;
  test_support::InProcessBus b;
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  std::map<std::string, std::unique_ptr<ScopedProcess>> agents;
  for (const std::string kind : {"manager", "view", "deletion", "asset", "motion"}) {
    agents[kind] = std::make_unique<ScopedProcess>(test_support::spawn({bin("chatsim-" + kind), "--bus", b.endpoint()}, "/dev/null"));
    ASSERT_TRUE(watcher.wait_for(kind, 5s)) << kind;
  }
  const auto file = test_support::temp_path("agents.mcap");
  fs::remove(file);
  ScopedProcess recorder(test_support::spawn(
      {bin("chatsim"), "bag", "record", "--all", "-o", file.string(), "--bus", b.endpoint()}, "/dev/null"));
  ASSERT_TRUE(watcher.wait_for("bag-record-" + std::to_string(recorder.pid), 5s));
  const std::string plan = bin("chatsim") + " plan --bus " + b.endpoint() + " --scene " + scene.string() +
                           " 'Add a white SUV in the right front that turns right at the intersection.'";
  const auto expected = plan_edit_state(plan);
  stop_recording(recorder);

  agents["motion"].reset();  // gone: only the recording can answer for it now
  ScopedProcess mock(test_support::spawn(
      {bin("chatsim-mock"), "--agent", "motion", "--bag", file.string(), "--bus", b.endpoint()}, "/dev/null"));
  ASSERT_TRUE(watcher.wait_for("motion", mock.pid, 5s));
  const auto replayed = plan_edit_state(plan);
  auto strip_rounds = [](nlohmann::json j) {
    j.erase("rounds");  // the same, but in a new conversation
    return j;
  };
  EXPECT_EQ(strip_rounds(replayed), strip_rounds(expected));
  EXPECT_EQ(replayed["added"].size(), 1u);
}
