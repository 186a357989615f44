#include <gtest/gtest.h>

#include "processes/agent_liveness.hpp"

using chatsim::processes::AgentLiveness;

TEST(AgentLiveness, ARequestIsLostWhenEveryReceiverDiesOrRestarts) {
  AgentLiveness l(3.0, 1.0);
  l.observe("motion", "motion", 100, 0.5, false, 0.0);
  l.observe("view", "view", 200, 0.5, false, 0.0);
  const auto sent = l.snapshot("motion", 0.1);
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_FALSE(l.lost("motion", sent, 1.0));  // within 3 beats
  l.observe("motion", "motion", 100, 0.5, false, 1.0);
  EXPECT_FALSE(l.lost("motion", sent, 2.4));
  const auto silent = l.lost("motion", sent, 2.6);  // 1.6 s without a beat
  ASSERT_TRUE(silent);
  EXPECT_NE(silent->find("fell silent"), std::string::npos) << *silent;
  l.observe("motion", "motion", 101, 0.5, false, 2.7);  // respawned: the request died with pid 100
  const auto restarted = l.lost("motion", sent, 2.8);
  ASSERT_TRUE(restarted);
  EXPECT_NE(restarted->find("restarted"), std::string::npos) << *restarted;
  EXPECT_FALSE(l.lost("motion", l.snapshot("motion", 2.8), 2.9));  // a new request reaches the new one
  l.observe("view", "view", 200, 0.5, true, 3.0);
  EXPECT_TRUE(l.lost("view", {{"view", 200}}, 3.0));          // said it was stopping
  EXPECT_FALSE(l.lost("asset", l.snapshot("asset", 3.0), 3.0));  // nothing known: wait for the deadline
}
