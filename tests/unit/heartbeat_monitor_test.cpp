#include <gtest/gtest.h>

#include "common/bus/heartbeat_monitor.hpp"

using chatsim::bus::HeartbeatMonitor;

TEST(HeartbeatMonitor, ReportsSilentNodesByName) {
  HeartbeatMonitor m(4.0, 1.0);
  m.observe("motion", 0.0, 0.5);
  m.observe("view", 0.0, 0.5);
  m.observe("view", 2.5, 0.5);
  EXPECT_TRUE(m.alive("view", 3.0));
  EXPECT_FALSE(m.alive("motion", 3.0));
  EXPECT_EQ(m.overdue(3.0), std::vector<std::string>{"motion"});
}

TEST(HeartbeatMonitor, AStoppingNodeIsNotAFailure) {
  HeartbeatMonitor m;
  m.observe("asset", 0.0, 0.5, /*stopping=*/true);
  EXPECT_TRUE(m.overdue(100.0).empty());
  EXPECT_FALSE(m.alive("asset", 0.1));
  EXPECT_TRUE(m.seen("asset"));
  EXPECT_FALSE(m.seen("manager"));
}

TEST(HeartbeatMonitor, TimeoutScalesWithTheNodesPeriod) {
  HeartbeatMonitor m(4.0, 1.0);
  m.observe("slow", 0.0, 5.0);
  EXPECT_TRUE(m.alive("slow", 19.0));
  EXPECT_FALSE(m.alive("slow", 21.0));
}
