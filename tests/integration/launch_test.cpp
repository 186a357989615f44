// `chatsim launch` with real processes: bring-up, readiness, respawn, mocks, and a clean stop
// that leaves no process behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/launch/process_tree.hpp"
#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::ScopedProcess;

namespace {

std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("chatsim-test-" + std::to_string(getpid()) + "-" + name);
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

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

// Watches heartbeats on a launched bus: node name -> latest pid.
struct Watcher {
  std::unique_ptr<bus::Node> node;
  std::map<std::string, int> pids;
  explicit Watcher(const std::string& endpoint) {
    bus::NodeOptions o{"test-watcher", "test", endpoint};
    o.heartbeat_period = 0ms;
    node = std::make_unique<bus::Node>(o);
    node->subscribe(std::string(bus::topics::kHeartbeat), [this](const bus::Message& m) {
      const auto* hb = m.payload<msgs::Heartbeat>();
      if (hb->state() != msgs::NodeState::Stopping) pids[std::string(bus::view(hb->node()))] = hb->pid();
    });
    node->start();
  }
  template <class Pred>
  bool until(Pred pred, std::chrono::milliseconds t) {
    const auto end = std::chrono::steady_clock::now() + t;
    while (!pred() && std::chrono::steady_clock::now() < end) node->spin_once(20ms);
    return pred();
  }
};

}  // namespace

TEST(Launch, LocalYamlBringsUpEveryProcessAndCtrlCLeavesNoneBehind) {
  const auto ep_file = temp_path("ep1");
  std::filesystem::remove(ep_file);
  ScopedProcess launcher(test_support::spawn(
      {bin("chatsim"), "launch", std::string(CHATSIM_SOURCE_DIR) + "/launch/local.yaml", "--bus",
       "tcp://127.0.0.1:0", "--endpoint-file", ep_file.string()},
      temp_path("launch1.log").string()));
  const std::string endpoint = wait_endpoint(ep_file, 10s);
  ASSERT_FALSE(endpoint.empty()) << read_file(temp_path("launch1.log"));
  Watcher w(endpoint);
  const std::set<std::string> expected = {"bus", "manager", "view", "background", "deletion",
                                          "asset", "motion", "foreground"};
  ASSERT_TRUE(w.until([&] {
    for (const auto& n : expected) {
      if (!w.pids.count(n)) return false;
    }
    return true;
  }, 15s)) << read_file(temp_path("launch1.log"));
  const auto descendants = launch::descendants_of(launcher.pid);
  EXPECT_GE(descendants.size(), expected.size());
  w.node->shutdown();

  kill(launcher.pid, SIGINT);
  const auto status = launcher.wait(10s);
  ASSERT_TRUE(status) << "launcher did not stop";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0);
  for (const auto& [name, pid] : w.pids) EXPECT_FALSE(launch::process_alive(pid)) << name << " left running";
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

TEST(Launch, RespawnsAKilledAgentAndSwapsMocksIn) {
  const auto file = temp_path("respawn.yaml");
  std::ofstream(file) << "bus: tcp://127.0.0.1:0\n"
                         "processes:\n"
                         "  - {name: bus, kind: bus, executable: chatsim-bus}\n"
                         "  - {name: view, executable: chatsim-view, respawn: on-failure, respawn_delay_s: 0.1}\n"
                         "  - {name: motion, executable: chatsim-motion}\n";
  const auto ep_file = temp_path("ep2");
  std::filesystem::remove(ep_file);
  ScopedProcess launcher(test_support::spawn(
      {bin("chatsim"), "launch", file.string(), "--endpoint-file", ep_file.string(), "--mock",
       "motion=" + std::string(CHATSIM_SOURCE_DIR) + "/launch/mocks/motion.yaml"},
      temp_path("launch3.log").string()));
  const std::string endpoint = wait_endpoint(ep_file, 10s);
  ASSERT_FALSE(endpoint.empty()) << read_file(temp_path("launch3.log"));
  Watcher w(endpoint);
  ASSERT_TRUE(w.until([&] { return w.pids.count("view") && w.pids.count("motion"); }, 10s));

  // The mock answers in the motion agent's place.
  flatbuffers::FlatBufferBuilder fbb;
  auto req = msgs::CreateAgentRequestDirect(fbb, "motion", "plan", "", "{}");
  auto r = w.node->call(bus::topics::agent_request("motion"), fbb, msgs::Payload::AgentRequest, req.Union(), 3s);
  ASSERT_TRUE(r.ok()) << r.error_message;
  EXPECT_TRUE(r.response->payload<msgs::AgentResponse>()->ok());

  const int first = w.pids["view"];
  kill(first, SIGKILL);
  EXPECT_TRUE(w.until([&] { return w.pids["view"] != first; }, 5s)) << read_file(temp_path("launch3.log"));
  EXPECT_FALSE(launch::process_alive(first));

  const int second = w.pids["view"];
  kill(launcher.pid, SIGTERM);
  ASSERT_TRUE(launcher.wait(10s));
  EXPECT_FALSE(launch::process_alive(second));
}

TEST(Launch, BadLaunchFileIsRefusedWithFileAndLine) {
  const auto file = temp_path("bad.yaml");
  std::ofstream(file) << "processes:\n  - name: a\n    executable: x\n    respawn: maybe\n";
  const auto log = temp_path("bad.log");
  ScopedProcess launcher(test_support::spawn({bin("chatsim"), "launch", file.string()}, log.string()));
  const auto status = launcher.wait(5s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 2);
  EXPECT_NE(read_file(log).find(file.string() + ":4:14"), std::string::npos) << read_file(log);
}

TEST(Launch, MissingExecutableIsAClearFailure) {
  const auto file = temp_path("missing.yaml");
  std::ofstream(file) << "processes:\n  - {name: a, executable: chatsim-nonexistent, ready: none}\n";
  const auto log = temp_path("missing.log");
  ScopedProcess launcher(test_support::spawn({bin("chatsim"), "launch", file.string()}, log.string()));
  const auto status = launcher.wait(5s);
  ASSERT_TRUE(status);
  EXPECT_NE(WEXITSTATUS(*status), 0);
  EXPECT_NE(read_file(log).find("chatsim-nonexistent"), std::string::npos) << read_file(log);
}
