#include <gtest/gtest.h>

#include "common/bus/sequence_tracker.hpp"

using chatsim::bus::SequenceTracker;

TEST(SequenceTracker, InOrderHasNoGaps) {
  SequenceTracker t;
  for (uint64_t s = 1; s <= 10; ++s) EXPECT_EQ(t.observe("a", 1, "/t", s).missing, 0u);
  EXPECT_EQ(t.gaps(), 0u);
}

TEST(SequenceTracker, CountsMissingMessages) {
  SequenceTracker t;
  t.observe("a", 1, "/t", 1);
  t.observe("a", 1, "/t", 2);
  EXPECT_EQ(t.observe("a", 1, "/t", 6).missing, 3u);
  EXPECT_EQ(t.observe("a", 1, "/t", 8).missing, 1u);
  EXPECT_EQ(t.gaps(), 4u);
}

TEST(SequenceTracker, StreamsAreSeparateBySenderAndTopic) {
  SequenceTracker t;
  t.observe("a", 1, "/t", 1);
  t.observe("b", 2, "/t", 100);   // another sender joins late: not a gap
  t.observe("a", 1, "/u", 50);    // another topic: its own stream
  t.observe("a", 1, "/t", 2);
  t.observe("b", 2, "/t", 101);
  EXPECT_EQ(t.gaps(), 0u);
}

TEST(SequenceTracker, DuplicatesAndRestartsAreNotGaps) {
  SequenceTracker t;
  t.observe("a", 1, "/t", 5);
  EXPECT_TRUE(t.observe("a", 1, "/t", 5).duplicate);
  EXPECT_TRUE(t.observe("a", 1, "/t", 3).duplicate);
  const auto r = t.observe("a", 2, "/t", 1);  // the publisher restarted
  EXPECT_TRUE(r.restarted);
  EXPECT_EQ(r.missing, 0u);
  EXPECT_EQ(t.observe("a", 2, "/t", 2).missing, 0u);
  EXPECT_EQ(t.gaps(), 0u);
  EXPECT_EQ(t.duplicates(), 2u);
  EXPECT_EQ(t.restarts(), 1u);
}
