// Real agent processes on a loopback bus: flags, readiness, answers, clean and fast exit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "tests/support/bus_fixture.hpp"
#include "tests/support/heartbeat_watcher.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::HeartbeatWatcher;
using test_support::ScopedProcess;

namespace {

const std::vector<std::string> kProcesses = {"chatsim-manager", "chatsim-view", "chatsim-background",
                                             "chatsim-deletion", "chatsim-asset", "chatsim-motion",
                                             "chatsim-foreground", "chatsim-bus", "chatsim-mock", "chatsim"};

// The call was answered with a refusal (BadRequest) whose message says why.
template <class Response>
void expect_refused(const bus::CallResult& r, const std::string& why) {
  ASSERT_TRUE(r.ok()) << r.error_message;
  const auto* resp = r.response->template payload<Response>();
  ASSERT_NE(resp, nullptr);
  EXPECT_FALSE(resp->ok());
  ASSERT_NE(resp->error(), nullptr);
  EXPECT_EQ(resp->error()->code(), msgs::ErrorCode::BadRequest);
  EXPECT_NE(bus::view(resp->error()->message()).find(why), std::string_view::npos) << bus::view(resp->error()->message());
}

}  // namespace

TEST(Processes, EveryProcessHasHelp) {
  for (const auto& p : kProcesses) {
    ScopedProcess proc(test_support::spawn({bin(p), "--help"}, "/dev/null"));
    const auto status = proc.wait(5s);
    ASSERT_TRUE(status) << p;
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << p;
  }
}

TEST(Processes, BadFlagsExitWithUsageCode) {
  ScopedProcess proc(test_support::spawn({bin("chatsim-motion"), "--no-such-flag"}, "/dev/null"));
  const auto status = proc.wait(5s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 2);
}

TEST(Processes, CommandsGivenAMissingSceneExitWithUsageCodeNamingIt) {
  const auto dir = chatsim::scratch::dir() / ("chatsim-missing-" + std::to_string(::getpid()));
  const std::string scene = (dir / "no-such-scene").string(), log = (dir / "log.txt").string();
  std::filesystem::create_directories(dir);
  const std::vector<std::vector<std::string>> commands = {
      {"light", "estimate", "--scene", scene, "--out", (dir / "sky.exr").string()},
      {"render", "--model", (dir / "m.gs").string(), "--scene", scene, "--out", (dir / "out").string()},
      {"eval", "nvs", "--scene", scene, "--model", (dir / "m.gs").string()},
      {"eval", "deletion", "--scene", scene},
      {"eval", "light", "--scene", scene},
      {"bench", "deletion", "--scene", scene, "--out", (dir / "deletion.json").string()},
      {"bench", "nvs", "--scene", scene, "--out", (dir / "nvs.json").string()}};
  for (auto args : commands) {
    args.insert(args.begin(), bin("chatsim"));
    ScopedProcess proc(test_support::spawn(args, log));
    const auto status = proc.wait(10s);
    ASSERT_TRUE(status) << args[1];
    EXPECT_EQ(WEXITSTATUS(*status), 2) << args[1] << " " << args[2];
    EXPECT_NE(test_support::read_file(log).find("no-such-scene"), std::string::npos) << test_support::read_file(log);
  }
  std::filesystem::remove_all(dir);
}

TEST(Processes, NoBusIsExitCode3) {
  ScopedProcess proc(test_support::spawn(
      {bin("chatsim-view"), "--bus", "tcp://127.0.0.1:1", "--handshake-timeout-ms", "300"}, "/dev/null"));
  const auto status = proc.wait(5s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 3);
}

// Each agent beats, answers an action it does not have with a bad-request error, and exits
// cleanly within 1 s of SIGTERM and SIGINT.
TEST(Processes, AgentsAnswerAndStopWithinOneSecond) {
  test_support::InProcessBus b;
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  int signal_index = 0;
  for (const std::string kind : {"view", "background", "deletion", "asset", "motion", "foreground"}) {
    ScopedProcess proc(test_support::spawn({bin("chatsim-" + kind), "--bus", b.endpoint()}, "/dev/null"));
    ASSERT_TRUE(watcher.wait_for(kind, 5s)) << kind;
    EXPECT_EQ(watcher.pids[kind], proc.pid);

    flatbuffers::FlatBufferBuilder fbb;
    auto req = msgs::CreateAgentRequestDirect(fbb, kind.c_str(), "decide", "", "{}");
    auto r = client.call(bus::topics::agent_request(kind), fbb, msgs::Payload::AgentRequest, req.Union(), 3s);
    ASSERT_TRUE(r.ok()) << kind << ": " << r.error_message;
    const auto* resp = r.response->payload<msgs::AgentResponse>();
    ASSERT_NE(resp, nullptr);
    EXPECT_FALSE(resp->ok());
    ASSERT_NE(resp->error(), nullptr);
    EXPECT_EQ(resp->error()->code(), msgs::ErrorCode::BadRequest) << kind;
    EXPECT_EQ(bus::view(resp->error()->node()), kind);

    const double t0 = mono_s();
    kill(proc.pid, (signal_index++ % 2) ? SIGINT : SIGTERM);
    const auto status = proc.wait(2s);
    ASSERT_TRUE(status) << kind << " did not exit";
    EXPECT_LT(mono_s() - t0, 1.0) << kind;
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << kind;
  }
}

// A request that takes minutes (training a radiance field) does not delay the exit: the agent
// leaves within a second of SIGTERM, mid-request.
TEST(Processes, ABusyAgentStillStopsWithinOneSecond) {
  const auto root = test_support::temp_path("busy-agent");
  std::filesystem::create_directories(root);
  ScopedProcess gen(test_support::spawn({bin("chatsim"), "scene", "demo", "--preset", "small", "--no-plates", "--no-views",
                                         "--out", (root / "scene").string()}, "/dev/null"));
  const auto made = gen.wait(120s);
  ASSERT_TRUE(made && WIFEXITED(*made) && WEXITSTATUS(*made) == 0);
  test_support::InProcessBus b;
  ScopedProcess proc(test_support::spawn({"/usr/bin/env", "CHATSIM_CACHE=" + (root / "cache").string(),
                                          "CHATSIM_TRAIN_ITERATIONS=100000", bin("chatsim-background"), "--bus", b.endpoint()},
                                         "/dev/null"));
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  ASSERT_TRUE(watcher.wait_for("background", 5s));
  flatbuffers::FlatBufferBuilder fbb;
  const std::string scene = (root / "scene").string();
  auto req = msgs::CreateAgentRequestDirect(fbb, "background", "ensure_model", scene.c_str(), "{}");
  const auto r = client.call(bus::topics::agent_request("background"), fbb, msgs::Payload::AgentRequest, req.Union(), 1500ms);
  EXPECT_FALSE(r.ok());  // still training
  const double t0 = mono_s();
  kill(proc.pid, SIGTERM);
  const auto status = proc.wait(3s);
  ASSERT_TRUE(status) << "the busy agent did not exit";
  EXPECT_LT(mono_s() - t0, 1.0);
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0);
  std::filesystem::remove_all(root);
}

// A missing scene or an unknown rendering preset is refused by name before the round is decided.
TEST(Processes, ManagerRefusesAMissingSceneOrUnknownPresetNamingIt) {
  test_support::InProcessBus b;
  ScopedProcess proc(test_support::spawn({bin("chatsim-manager"), "--bus", b.endpoint()}, "/dev/null"));
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  ASSERT_TRUE(watcher.wait_for("manager", 5s));
  flatbuffers::FlatBufferBuilder fbb;
  auto req = msgs::CreateChatRequestDirect(fbb, "c1", "scene", "remove all cars");
  const auto r = client.call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(), 5s);
  expect_refused<msgs::ChatResponse>(r, "scene");
  if (const auto* resp = r.ok() ? r.response->payload<msgs::ChatResponse>() : nullptr) {
    EXPECT_EQ(bus::view(resp->conversation_id()), "c1");
  }

  const std::string out = test_support::temp_path("preset-out").string();
  flatbuffers::FlatBufferBuilder fbb2;
  auto bad_preset = msgs::CreateChatRequestDirect(fbb2, "c2", "/tmp", "remove all cars", true, out.c_str(), "ultra");
  expect_refused<msgs::ChatResponse>(client.call(bus::topics::kChatRequest, fbb2, msgs::Payload::ChatRequest, bad_preset.Union(), 5s),
                                     "unknown rendering preset 'ultra'");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Processes, MockAnswersFromItsScript) {
  test_support::InProcessBus b;
  const std::string script = std::string(CHATSIM_SOURCE_DIR) + "/launch/mocks/motion.yaml";
  ScopedProcess proc(test_support::spawn(
      {bin("chatsim-mock"), "--script", script, "--name", "motion-mock", "--bus", b.endpoint()}, "/dev/null"));
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  ASSERT_TRUE(watcher.wait_for("motion-mock", 5s));
  flatbuffers::FlatBufferBuilder fbb;
  auto req = msgs::CreateAgentRequestDirect(fbb, "motion", "plan", "", R"({"asset":"porsche"})");
  const double t0 = mono_s();
  auto r = client.call(bus::topics::agent_request("motion"), fbb, msgs::Payload::AgentRequest, req.Union(), 3s);
  ASSERT_TRUE(r.ok()) << r.error_message;
  EXPECT_GE(mono_s() - t0, 0.05);  // the script's delay_ms
  const auto* resp = r.response->payload<msgs::AgentResponse>();
  ASSERT_TRUE(resp->ok());
  const auto result = nlohmann::json::parse(bus::view(resp->result_json()));
  EXPECT_DOUBLE_EQ(result["trajectory"][0]["x"].get<double>(), 12.0);
}

TEST(Processes, MockRefusesABadScriptNamingIt) {
  const auto path = test_support::temp_path("bad-mock.yaml");
  std::ofstream(path) << "agent: motion\nresponses:\n  - reslt: {}\n";
  const std::string log = path.string() + ".log";
  ScopedProcess proc(test_support::spawn({bin("chatsim-mock"), "--script", path.string()}, log));
  const auto status = proc.wait(5s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 2);
  const std::string text = test_support::read_file(log);
  EXPECT_NE(text.find("bad-mock.yaml:3:5"), std::string::npos) << text;
}

TEST(Processes, MalformedArgumentsAreABadRequestNotACrash) {
  test_support::InProcessBus b;
  ScopedProcess proc(test_support::spawn({bin("chatsim-view"), "--bus", b.endpoint()}, "/dev/null"));
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  ASSERT_TRUE(watcher.wait_for("view", 5s));
  flatbuffers::FlatBufferBuilder fbb;
  auto req = msgs::CreateAgentRequestDirect(fbb, "view", "decide", "", "{not json");
  auto r = client.call(bus::topics::agent_request("view"), fbb, msgs::Payload::AgentRequest, req.Union(), 3s);
  ASSERT_TRUE(r.ok()) << r.error_message;
  const auto* resp = r.response->payload<msgs::AgentResponse>();
  EXPECT_FALSE(resp->ok());
  EXPECT_EQ(resp->error()->code(), msgs::ErrorCode::BadRequest);
  EXPECT_NE(bus::view(resp->error()->message()).find("args_json"), std::string::npos);
  kill(proc.pid, SIGTERM);
  const auto status = proc.wait(2s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 0);
}

// With --allowed-root, a request naming a scene outside it is refused, "..": tricks included.
TEST(Processes, PathsOutsideTheAllowedRootsAreRefused) {
  const auto root = test_support::temp_path("allowed-root");
  std::filesystem::create_directories(root);
  test_support::InProcessBus b;
  ScopedProcess proc(test_support::spawn(
      {bin("chatsim-manager"), "--bus", b.endpoint(), "--allowed-root", root.string()}, "/dev/null"));
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  ASSERT_TRUE(watcher.wait_for("manager", 5s));
  for (const std::string& scene : {std::string("/etc"), (root / ".." / "elsewhere").string()}) {
    flatbuffers::FlatBufferBuilder fbb;
    auto req = msgs::CreateChatRequestDirect(fbb, "c1", scene.c_str(), "remove all cars");
    expect_refused<msgs::ChatResponse>(
        client.call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(), 5s), "outside the allowed folders");
  }
}

// A rendering agent refuses a stage folder or model outside its allowed roots, even when the
// scene is inside: a request cannot make it write (or read) elsewhere.
TEST(Processes, RenderingStagePathsOutsideTheAllowedRootsAreRefused) {
  const auto root = test_support::temp_path("allowed-root-render");
  std::filesystem::create_directories(root);
  test_support::InProcessBus b;
  ScopedProcess proc(test_support::spawn(
      {bin("chatsim-background"), "--bus", b.endpoint(), "--allowed-root", root.string()}, "/dev/null"));
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  ASSERT_TRUE(watcher.wait_for("background", 5s));
  const std::string scene = (root / "scene").string();
  for (const std::string& args : {std::string(R"({"out": "/tmp/../etc/chatsim-stage"})"), R"({"out": ")" + scene + R"(", "model": "/etc/passwd"})"}) {
    flatbuffers::FlatBufferBuilder fbb;
    auto req = msgs::CreateAgentRequestDirect(fbb, "background", "render", scene.c_str(), args.c_str());
    expect_refused<msgs::AgentResponse>(
        client.call(bus::topics::agent_request("background"), fbb, msgs::Payload::AgentRequest, req.Union(), 5s),
        "outside the allowed folders");
  }
}
