// An agent killed with -9 in the middle of a request: the manager says which agent failed
// within 5 s (from its heartbeats, not the 60 s deadline), and once the agent is back the
// next request succeeds.
#include <gtest/gtest.h>

#include <csignal>
#include <map>
#include <fstream>
#include <thread>

#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "tests/support/bus_fixture.hpp"
#include "tests/support/heartbeat_watcher.hpp"
#include "tests/support/subprocess.hpp"
#include "common/scene/demo_layout.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::HeartbeatWatcher;
using test_support::ScopedProcess;

namespace {

bus::CallResult chat(bus::Node& client, const std::string& scene, const std::string& command) {
  flatbuffers::FlatBufferBuilder fbb;
  const auto req = msgs::CreateChatRequestDirect(fbb, "faults", scene.c_str(), command.c_str());
  return client.call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(), 30s);
}

}  // namespace

// For each agent the manager calls: a stand-in that takes 8 s over everything is killed -9
// 1.5 s into a request that needs it.
TEST(Faults, AnAgentKilledMidRequestIsReportedWithinFiveSeconds) {
  const auto scene = test_support::temp_path("faults-scene").string();
  scene::save_scene(scene::demo_layout({}), scene);
  const auto script_for = [](const std::string& kind) {
    const auto path = test_support::temp_path("slow-" + kind + ".yaml");
    std::ofstream(path) << "agent: " << kind << "\nresponses:\n  - delay_ms: 8000\n    result: {}\n";
    return path;
  };
  const std::map<std::string, std::string> command_for = {{"view", "Move the view 1 m up."},
                                                          {"deletion", "Delete the red car."},
                                                          {"asset", "Add a red car 20 m ahead."},
                                                          {"motion", "Add a red car 20 m ahead."}};
  for (const auto& [victim, command] : command_for) {
    SCOPED_TRACE(victim);
    test_support::InProcessBus b;
    bus::Node client(b.options("client"), b.context());
    HeartbeatWatcher watcher(client);
    client.start();
    std::vector<std::unique_ptr<ScopedProcess>> agents;
    for (const std::string kind : {"manager", "view", "deletion", "asset", "motion"}) {
      if (kind == victim) continue;
      agents.push_back(std::make_unique<ScopedProcess>(test_support::spawn({bin("chatsim-" + kind), "--bus", b.endpoint()}, "/dev/null")));
      ASSERT_TRUE(watcher.wait_for(kind, 5s)) << kind;
    }
    auto slow = std::make_unique<ScopedProcess>(test_support::spawn(
        {bin("chatsim-mock"), "--script", script_for(victim).string(), "--bus", b.endpoint()}, "/dev/null"));
    ASSERT_TRUE(watcher.wait_for(victim, 5s));

    double killed_at = 0;
    std::thread killer([&] {
      std::this_thread::sleep_for(1500ms);
      killed_at = mono_s();
      kill(slow->pid, SIGKILL);
    });
    const auto r = chat(client, scene, command);
    const double answered_at = mono_s();
    killer.join();
    ASSERT_TRUE(r.ok()) << r.error_message;
    const auto* resp = r.response->payload<msgs::ChatResponse>();
    ASSERT_NE(resp, nullptr);
    EXPECT_FALSE(resp->ok());
    ASSERT_NE(resp->error(), nullptr);
    const std::string why(bus::view(resp->error()->message()));
    EXPECT_NE(why.find("the " + victim + " agent failed"), std::string::npos) << why;
    EXPECT_LT(answered_at - killed_at, 5.0) << why;

    // The agent comes back (as the launcher would respawn it): the next request succeeds.
    slow.reset();
    ScopedProcess back(test_support::spawn({bin("chatsim-" + victim), "--bus", b.endpoint()}, "/dev/null"));
    ASSERT_TRUE(watcher.wait_for(victim, back.pid, 5s));
    const auto again = chat(client, scene, command);
    ASSERT_TRUE(again.ok()) << again.error_message;
    EXPECT_TRUE(again.response->payload<msgs::ChatResponse>()->ok());
  }
}

// The manager itself killed mid-round: chatsim plan says so within 5 s (exit code 3).
TEST(Faults, AManagerKilledMidRoundIsReportedByPlan) {
  const auto scene = test_support::temp_path("faults-scene-2").string();
  scene::save_scene(scene::demo_layout({}), scene);
  test_support::InProcessBus b;
  bus::Node client(b.options("client"), b.context());
  HeartbeatWatcher watcher(client);
  client.start();
  std::vector<std::unique_ptr<ScopedProcess>> agents;
  for (const std::string kind : {"manager", "view", "deletion", "asset"}) {
    agents.push_back(std::make_unique<ScopedProcess>(test_support::spawn({bin("chatsim-" + kind), "--bus", b.endpoint()}, "/dev/null")));
    ASSERT_TRUE(watcher.wait_for(kind, 5s)) << kind;
  }
  const auto script = test_support::temp_path("slow-motion-2.yaml");
  std::ofstream(script) << "agent: motion\nresponses:\n  - delay_ms: 20000\n    result: {}\n";
  ScopedProcess slow(test_support::spawn({bin("chatsim-mock"), "--script", script.string(), "--bus", b.endpoint()}, "/dev/null"));
  ASSERT_TRUE(watcher.wait_for("motion", 5s));
  const auto log = test_support::temp_path("plan-manager-dies.log");
  ScopedProcess plan(test_support::spawn(
      {bin("chatsim"), "plan", "--bus", b.endpoint(), "--scene", scene, "Add a red car 20 m ahead."}, log.string()));
  std::this_thread::sleep_for(2s);
  const double killed_at = mono_s();
  kill(agents.front()->pid, SIGKILL);  // the manager
  const auto status = plan.wait(10s);
  ASSERT_TRUE(status) << "plan did not notice";
  EXPECT_LT(mono_s() - killed_at, 5.0);
  EXPECT_EQ(WEXITSTATUS(*status), 3);
  EXPECT_NE(test_support::read_file(log).find("the manager agent failed"), std::string::npos) << test_support::read_file(log);
}
