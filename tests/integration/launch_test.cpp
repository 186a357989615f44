// `chatsim launch` with real processes: bring-up, readiness, respawn, mocks, and a clean stop
// that leaves no process behind.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/launch/launcher.hpp"
#include "common/launch/process_tree.hpp"
#include "tests/support/heartbeat_watcher.hpp"
#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::read_file;
using test_support::ScopedProcess;
using test_support::temp_path;

namespace {

std::string wait_endpoint(const std::filesystem::path& file, std::chrono::milliseconds t) {
  const auto end = std::chrono::steady_clock::now() + t;
  while (std::chrono::steady_clock::now() < end) {
    std::string ep;
    std::ifstream in(file);
    if (in >> ep && !ep.empty()) return ep;
    std::this_thread::sleep_for(20ms);
  }
  return "";
}

// A `chatsim launch` run whose bus endpoint the test reads back, watched through a node of ours.
struct LaunchedGraph {
  std::filesystem::path log;
  ScopedProcess launcher;
  std::string endpoint;
  std::unique_ptr<bus::Node> node;
  std::unique_ptr<test_support::HeartbeatWatcher> watcher;

  LaunchedGraph(const std::string& tag, std::vector<std::string> args)
      : log(temp_path(tag + ".log")), launcher(start(tag, std::move(args), log)) {
    endpoint = wait_endpoint(temp_path(tag + ".endpoint"), 10s);
    if (endpoint.empty()) return;
    bus::NodeOptions o;
    o.name = "test-watcher";
    o.kind = "test";
    o.bus = endpoint;
    o.heartbeat_period = 0ms;
    node = std::make_unique<bus::Node>(o);
    watcher = std::make_unique<test_support::HeartbeatWatcher>(*node);
    node->start();
  }

  static pid_t start(const std::string& tag, std::vector<std::string> args,
                     const std::filesystem::path& log) {
    const auto ep_file = temp_path(tag + ".endpoint");
    std::filesystem::remove(ep_file);
    args.insert(args.begin(), {bin("chatsim"), "launch"});
    args.insert(args.end(), {"--endpoint-file", ep_file.string()});
    return test_support::spawn(args, log.string());
  }
};

// Runs `chatsim launch FILE` to its end; returns (exit status, what it printed).
std::pair<std::optional<int>, std::string> launch_to_exit(const std::string& tag, const std::string& yaml) {
  const auto file = temp_path(tag + ".yaml");
  std::ofstream(file) << yaml;
  const auto log = temp_path(tag + ".log");
  ScopedProcess launcher(test_support::spawn({bin("chatsim"), "launch", file.string()}, log.string()));
  const auto status = launcher.wait(5s);
  return {status, read_file(log)};
}

}  // namespace

TEST(Launch, LocalYamlBringsUpEveryProcessAndCtrlCLeavesNoneBehind) {
  LaunchedGraph g("local", {std::string(CHATSIM_SOURCE_DIR) + "/launch/local.yaml", "--bus",
                            "tcp://127.0.0.1:0"});
  ASSERT_FALSE(g.endpoint.empty()) << read_file(g.log);
  const std::set<std::string> expected = {"bus", "manager", "view", "background", "deletion",
                                          "asset", "motion", "foreground"};
  ASSERT_TRUE(g.watcher->until([&] {
    for (const auto& n : expected) {
      if (!g.watcher->pids.count(n)) return false;
    }
    return true;
  }, 15s)) << read_file(g.log);
  const auto descendants = launch::descendants_of(g.launcher.pid);
  EXPECT_GE(descendants.size(), expected.size());
  g.node->shutdown();

  kill(g.launcher.pid, SIGINT);
  const auto status = g.launcher.wait(10s);
  ASSERT_TRUE(status) << "launcher did not stop";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0);
  for (const auto& [name, pid] : g.watcher->pids) EXPECT_FALSE(launch::process_alive(pid)) << name << " left running";
  for (pid_t p : descendants) EXPECT_FALSE(launch::process_alive(p)) << "pid " << p << " left running";
}

TEST(Launch, GrandchildrenThatLeftTheProcessGroupAreStoppedToo) {
  const auto file = temp_path("grand.yaml");
  std::ofstream(file) << "processes:\n"
                         "  - name: shell\n"
                         "    executable: /bin/sh\n"
                         "    args: [-c, 'setsid sleep 300 & sleep 300 & wait']\n"
                         "    bus_args: false\n"
                         "    ready: none\n"
                         "    respawn: never\n";
  ScopedProcess launcher(test_support::spawn({bin("chatsim"), "launch", file.string()}, "/dev/null"));
  std::vector<pid_t> tree;
  for (int i = 0; i < 200 && tree.size() < 3; ++i) {
    std::this_thread::sleep_for(20ms);
    tree = launch::descendants_of(launcher.pid);
  }
  ASSERT_GE(tree.size(), 3u) << "sh and two sleeps expected";
  kill(launcher.pid, SIGINT);
  const auto status = launcher.wait(10s);
  ASSERT_TRUE(status);
  for (pid_t p : tree) EXPECT_FALSE(launch::process_alive(p)) << "pid " << p << " left running";
}

// Two launchers in one process (two chat sessions, each with its own agents): stopping one
// neither takes the other's exit statuses (it would wait for them forever) nor ends its processes.
TEST(Launch, TwoLaunchersInOneProcessEachStopOnlyTheirOwn) {
  const std::string yaml = "processes:\n  - {name: sleeper, executable: /bin/sleep, args: ['300'], bus_args: false, ready: none}\n";
  launch::Launcher outer(launch::parse_launch_file(yaml, "outer.yaml"), {});
  launch::Launcher inner(launch::parse_launch_file(yaml, "inner.yaml"), {});
  std::atomic<bool> stop_outer{false}, stop_inner{false};
  std::atomic<bool> inner_done{false};
  std::thread outer_thread([&] { outer.run(stop_outer); });
  std::thread inner_thread([&] {
    inner.run(stop_inner);
    inner_done = true;
  });
  std::vector<pid_t> sleepers;
  for (int i = 0; i < 250 && sleepers.size() < 2; ++i) {
    std::this_thread::sleep_for(20ms);
    sleepers = launch::children_of(getpid());
  }
  ASSERT_EQ(sleepers.size(), 2u);
  const auto before = std::set<pid_t>(sleepers.begin(), sleepers.end());
  stop_inner = true;
  for (int i = 0; i < 250 && !inner_done; ++i) std::this_thread::sleep_for(20ms);
  EXPECT_TRUE(inner_done) << "the inner launcher did not finish stopping";
  std::vector<pid_t> left;
  for (pid_t p : before)
    if (launch::process_alive(p)) left.push_back(p);
  EXPECT_EQ(left.size(), 1u) << "the outer launcher's process must survive the inner one's stop";
  stop_outer = true;
  outer_thread.join();
  inner_thread.join();
  for (pid_t p : before) EXPECT_FALSE(launch::process_alive(p)) << "pid " << p << " left running";
}

TEST(Launch, ChildrenEndWhenTheLauncherIsKilled) {
  const auto file = temp_path("orphans.yaml");
  std::ofstream(file) << "bus: tcp://127.0.0.1:0\n"
                         "processes:\n"
                         "  - {name: bus, kind: bus, executable: chatsim-bus}\n"
                         "  - {name: view, executable: chatsim-view}\n";
  LaunchedGraph g("orphans", {file.string()});
  ASSERT_FALSE(g.endpoint.empty()) << read_file(g.log);
  ASSERT_TRUE(g.watcher->wait_for("view", 10s));
  const auto children = launch::children_of(g.launcher.pid);
  ASSERT_EQ(children.size(), 2u);
  g.node->shutdown();
  kill(g.launcher.pid, SIGKILL);  // no chance to clean up: the children's death signal must
  ASSERT_TRUE(g.launcher.wait(5s));
  for (pid_t p : children) {
    bool ended = false;
    for (int i = 0; i < 100 && !ended; ++i) {
      ended = !launch::process_alive(p);
      std::this_thread::sleep_for(20ms);
    }
    EXPECT_TRUE(ended) << "pid " << p << " outlived its launcher";
  }
}

TEST(Launch, RespawnsAKilledAgentAndSwapsMocksIn) {
  const auto file = temp_path("respawn.yaml");
  std::ofstream(file) << "bus: tcp://127.0.0.1:0\n"
                         "processes:\n"
                         "  - {name: bus, kind: bus, executable: chatsim-bus}\n"
                         "  - {name: view, executable: chatsim-view, respawn: on-failure, respawn_delay_s: 0.1}\n"
                         "  - {name: motion, executable: chatsim-motion}\n";
  LaunchedGraph g("respawn", {file.string(), "--mock",
                              "motion=" + std::string(CHATSIM_SOURCE_DIR) + "/launch/mocks/motion.yaml"});
  ASSERT_FALSE(g.endpoint.empty()) << read_file(g.log);
  auto& pids = g.watcher->pids;
  ASSERT_TRUE(g.watcher->until([&] { return pids.count("view") && pids.count("motion"); }, 10s));

  // The mock answers in the motion agent's place.
  flatbuffers::FlatBufferBuilder fbb;
  auto req = msgs::CreateAgentRequestDirect(fbb, "motion", "plan", "", "{}");
  auto r = g.node->call(bus::topics::agent_request("motion"), fbb, msgs::Payload::AgentRequest, req.Union(), 3s);
  ASSERT_TRUE(r.ok()) << r.error_message;
  EXPECT_TRUE(r.response->payload<msgs::AgentResponse>()->ok());

  const int first = pids["view"];
  kill(first, SIGKILL);
  EXPECT_TRUE(g.watcher->until([&] { return pids["view"] != first; }, 5s)) << read_file(g.log);
  EXPECT_FALSE(launch::process_alive(first));

  const int second = pids["view"];
  kill(g.launcher.pid, SIGTERM);
  ASSERT_TRUE(g.launcher.wait(10s));
  EXPECT_FALSE(launch::process_alive(second));
}

TEST(Launch, BadLaunchFileIsRefusedWithFileAndLine) {
  const auto [status, log] = launch_to_exit("bad", "processes:\n  - name: a\n    executable: x\n    respawn: maybe\n");
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 2);
  EXPECT_NE(log.find(temp_path("bad.yaml").string() + ":4:14"), std::string::npos) << log;
}

TEST(Launch, MissingExecutableIsAClearFailure) {
  const auto [status, log] = launch_to_exit(
      "missing", "processes:\n  - {name: a, executable: chatsim-nonexistent, ready: none}\n");
  ASSERT_TRUE(status);
  EXPECT_NE(WEXITSTATUS(*status), 0);
  EXPECT_NE(log.find("chatsim-nonexistent"), std::string::npos) << log;
}

// The bus proxy killed with -9: the launcher respawns it on the same port, and the agents,
// never restarted, answer through the new proxy (ZeroMQ reconnects and re-subscribes).
TEST(Launch, AProxyRestartNeedsNoAgentRestart) {
  const auto file = temp_path("proxy-restart.yaml");
  std::ofstream(file) << "processes:\n"
                         "  - {name: bus, kind: bus, executable: chatsim-bus, respawn: always, respawn_delay_s: 0.2}\n"
                         "  - {name: view, executable: chatsim-view}\n";
  LaunchedGraph g("proxy-restart", {file.string(), "--bus", "tcp://127.0.0.1:0"});
  ASSERT_FALSE(g.endpoint.empty()) << read_file(g.log);
  ASSERT_TRUE(g.watcher->wait_for("view", 10s)) << read_file(g.log);
  ASSERT_TRUE(g.watcher->wait_for("bus", 10s)) << read_file(g.log);
  const int view_pid = g.watcher->pids["view"];
  const int bus_pid = g.watcher->pids["bus"];
  kill(bus_pid, SIGKILL);
  g.watcher->pids.clear();
  // The same view process beats again through the respawned proxy...
  ASSERT_TRUE(g.watcher->until([&] { return g.watcher->pids.count("bus") && g.watcher->pids["bus"] != bus_pid &&
                                            g.watcher->pids.count("view"); },
                               10s))
      << read_file(g.log);
  EXPECT_EQ(g.watcher->pids["view"], view_pid);
  // ... and answers requests, once its subscriptions have reached the new proxy: each socket
  // reconnects on its own timer, so a beat proves the view's publisher is back, not its
  // subscriber. A user's retry is what this models; it must succeed within seconds.
  bus::CallResult r;
  for (const auto end = std::chrono::steady_clock::now() + 10s; std::chrono::steady_clock::now() < end;) {
    flatbuffers::FlatBufferBuilder fbb;
    const auto req = msgs::CreateAgentRequestDirect(fbb, "view", "adjust", "", R"({"instruction": "move 5 m ahead"})");
    r = g.node->call(bus::topics::agent_request("view"), fbb, msgs::Payload::AgentRequest, req.Union(), 1s);
    if (r.ok()) break;
  }
  ASSERT_TRUE(r.ok()) << r.error_message;
  const auto* resp = r.response->payload<msgs::AgentResponse>();
  ASSERT_NE(resp, nullptr);
  EXPECT_TRUE(resp->ok());
  EXPECT_EQ(nlohmann::json::parse(bus::view(resp->result_json()))["view"]["translation_m"][0], 5.0);
  g.node->shutdown();
  kill(g.launcher.pid, SIGINT);
  EXPECT_TRUE(g.launcher.wait(10s));
}

// The bus proxy killed while the launcher still waits for an agent's first beat: its policy
// respawns it then too, and startup completes. (The launcher used to respawn only once every
// process was ready, and so timed out waiting for a beat that had no bus to travel on.)
TEST(Launch, ABusKilledDuringStartupIsRespawnedAndStartupCompletes) {
  const auto file = temp_path("startup-bus-kill.yaml");
  std::ofstream(file) << "processes:\n"
                         "  - {name: bus, kind: bus, executable: chatsim-bus, respawn: always, respawn_delay_s: 0.2}\n"
                         "  - {name: view, executable: chatsim-view}\n";
  LaunchedGraph g("startup-bus-kill", {file.string(), "--bus", "tcp://127.0.0.1:0"});
  ASSERT_FALSE(g.endpoint.empty()) << read_file(g.log);
  ASSERT_TRUE(g.watcher->wait_for("bus", 10s)) << read_file(g.log);
  const int bus_pid = g.watcher->pids["bus"];
  const auto log_has = [&](const std::string& text, std::chrono::milliseconds within) {
    for (const auto end = std::chrono::steady_clock::now() + within; std::chrono::steady_clock::now() < end;) {
      if (read_file(g.log).find(text) != std::string::npos) return true;
      std::this_thread::sleep_for(5ms);
    }
    return false;
  };
  // The moment the view is started, well before its first beat (it needs the bus for that).
  ASSERT_TRUE(log_has("started 'view'", 10s)) << read_file(g.log);
  ASSERT_EQ(read_file(g.log).find("processes ready"), std::string::npos) << "too late: the view was already ready";
  kill(bus_pid, SIGKILL);
  EXPECT_TRUE(log_has("all 2 processes ready", 15s)) << read_file(g.log);
  g.node->shutdown();
  kill(g.launcher.pid, SIGINT);
  EXPECT_TRUE(g.launcher.wait(10s));
}

// A launch file with curve_keys: every process gets the keys; a tool with the "cli" key sees
// the bus, a tool without keys is refused (exit code 3).
TEST(Launch, CurveKeysSecureTheWholeGraph) {
  const auto dir = temp_path("curve-graph");
  std::filesystem::remove_all(dir);
  ScopedProcess keys(test_support::spawn({bin("chatsim"), "keys", "new", "--dir", (dir / "keys").string(), "bus",
                                          "launch", "cli", "view"},
                                         "/dev/null"));
  ASSERT_TRUE(keys.wait(10s));
  const auto file = dir / "secure.yaml";
  std::ofstream(file) << "curve_keys: keys\nprocesses:\n"
                         "  - {name: bus, kind: bus, executable: chatsim-bus}\n"
                         "  - {name: view, executable: chatsim-view}\n";
  const auto ep_file = dir / "endpoint";
  ScopedProcess launcher(test_support::spawn(
      {bin("chatsim"), "launch", file.string(), "--bus", "tcp://127.0.0.1:0", "--endpoint-file", ep_file.string()},
      (dir / "launch.log").string()));
  const std::string endpoint = wait_endpoint(ep_file, 10s);
  ASSERT_FALSE(endpoint.empty()) << read_file(dir / "launch.log");
  std::this_thread::sleep_for(1s);  // the view agent comes up after the bus
  const auto seen = dir / "seen.log";
  ScopedProcess with_key(test_support::spawn(
      {"/usr/bin/env", "CHATSIM_CURVE_KEYS=" + (dir / "keys").string(), bin("chatsim"), "topic", "list", "--bus", endpoint,
       "--duration-s", "1.5"},
      seen.string()));
  auto status = with_key.wait(10s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 0) << read_file(seen);
  EXPECT_NE(read_file(seen).find("view"), std::string::npos) << read_file(seen) << read_file(dir / "launch.log");
  ScopedProcess without(test_support::spawn(
      {"/usr/bin/env", "-u", "CHATSIM_CURVE_KEYS", bin("chatsim"), "topic", "list", "--bus", endpoint}, "/dev/null"));
  status = without.wait(10s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 3);
  kill(launcher.pid, SIGINT);
  EXPECT_TRUE(launcher.wait(10s));
}
