// The manager's calls to other agents over a real (in-process) bus.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "processes/agent_liveness.hpp"
#include "processes/agent_process.hpp"
#include "tests/support/bus_fixture.hpp"

using namespace chatsim;
using namespace std::chrono_literals;

// Launched together, the manager may be asked to call an agent whose first heartbeat has not
// come yet: a request sent then would be lost and the call would wait out its whole deadline.
TEST(BusCaller, AnAgentStillStartingIsWaitedForNotMissed) {
  test_support::InProcessBus b;
  bus::Node manager(b.options("manager"), b.context());
  processes::AgentLiveness liveness;
  processes::watch_heartbeats(manager, liveness);
  manager.start();

  std::atomic<bool> stop{false};
  std::thread late([&] {
    std::this_thread::sleep_for(1s);
    auto o = b.options("motion", 100);
    o.kind = "motion";
    bus::Node motion(o, b.context());
    motion.serve(bus::topics::agent_request("motion"), [](const bus::Message&, flatbuffers::FlatBufferBuilder& fbb) {
      return bus::Node::Reply{msgs::Payload::AgentResponse,
                              msgs::CreateAgentResponseDirect(fbb, "motion", "plan", true, R"({"answered":true})").Union()};
    });
    motion.start();
    motion.spin(stop);
  });
  const auto call = processes::bus_caller(manager, 3s, &liveness);
  const double t0 = mono_s();
  const auto outcome = call("motion", agents::AgentCall{"plan", "", nlohmann::json::object(), 0});
  const double took = mono_s() - t0;
  stop = true;
  late.join();
  ASSERT_TRUE(outcome.ok) << outcome.message;
  EXPECT_TRUE(outcome.result["answered"].get<bool>());
  EXPECT_GT(took, 0.9);  // it did wait for the agent
  EXPECT_LT(took, 3.0);  // and did not wait out the deadline
}
