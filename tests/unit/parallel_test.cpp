// The parallel loops: every item once, the static one's fixed worker per item, and an item's
// exception rethrown to the caller after every thread has stopped.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "render/parallel.hpp"

namespace chatsim::render {
namespace {

TEST(Parallel, EveryItemRunsOnceOnEitherSchedule) {
  for (const bool fixed : {false, true}) {
    std::vector<std::atomic<int>> seen(1000);
    std::vector<int> worker_of(1000, -1);
    const auto body = [&](int i, int w) {
      ++seen[size_t(i)];
      worker_of[size_t(i)] = w;
    };
    if (fixed)
      parallel_for_workers_static(1000, 3, body);
    else
      parallel_for_workers(1000, 3, body);
    for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i].load(), 1) << "item " << i << (fixed ? " static" : " dynamic");
    if (!fixed) continue;
    for (size_t i = 0; i < worker_of.size(); ++i) ASSERT_EQ(worker_of[i], int(i % 3)) << "item " << i;
  }
}

TEST(Parallel, AnItemsExceptionReachesTheCaller) {
  const auto body = [](int i, int) {
    if (i == 17) throw std::runtime_error("item 17");
  };
  EXPECT_THROW(parallel_for_workers(100, 4, body), std::runtime_error);
  EXPECT_THROW(parallel_for_workers_static(100, 4, body), std::runtime_error);
}

}  // namespace
}  // namespace chatsim::render
