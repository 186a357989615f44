#include <gtest/gtest.h>

#include "common/launch/backoff.hpp"

using namespace chatsim::launch;

TEST(Backoff, NeverRestarts) {
  RespawnBackoff b(RespawnPolicy::Never, {});
  EXPECT_FALSE(b.on_exit(true, 1.0));
}

TEST(Backoff, OnFailureIgnoresCleanExits) {
  RespawnBackoff b(RespawnPolicy::OnFailure, {});
  EXPECT_FALSE(b.on_exit(false, 1.0));
  EXPECT_TRUE(b.on_exit(true, 1.0));
}

TEST(Backoff, DelaysDoubleUpToTheMaximumThenGiveUp) {
  BackoffConfig c;
  c.initial_delay_s = 0.5;
  c.max_delay_s = 3.0;
  c.max_respawns = 5;
  RespawnBackoff b(RespawnPolicy::Always, c);
  EXPECT_DOUBLE_EQ(*b.on_exit(false, 0.1), 0.5);
  EXPECT_DOUBLE_EQ(*b.on_exit(true, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(*b.on_exit(true, 0.1), 2.0);
  EXPECT_DOUBLE_EQ(*b.on_exit(true, 0.1), 3.0);
  EXPECT_DOUBLE_EQ(*b.on_exit(true, 0.1), 3.0);
  EXPECT_FALSE(b.on_exit(true, 0.1));
  EXPECT_TRUE(b.exhausted());
}

TEST(Backoff, AStableRunResetsTheBackoff) {
  BackoffConfig c;
  c.stable_after_s = 10;
  RespawnBackoff b(RespawnPolicy::Always, c);
  b.on_exit(true, 0.1);
  b.on_exit(true, 0.1);
  EXPECT_DOUBLE_EQ(*b.on_exit(true, 60.0), c.initial_delay_s);
}

TEST(Backoff, ParsesPolicies) {
  EXPECT_EQ(parse_respawn_policy("on-failure"), RespawnPolicy::OnFailure);
  EXPECT_FALSE(parse_respawn_policy("sometimes"));
}
