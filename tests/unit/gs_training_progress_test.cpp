#include <gtest/gtest.h>

#include "render/gs/trainer.hpp"

namespace chatsim::render::gs {
namespace {

TEST(TrainingWorkDone, CoarseIterationsCountLessThanFullOnes) {
  // 1800 iterations, the first 540 at half resolution.
  EXPECT_DOUBLE_EQ(training_work_done(0, 1800, 0.3f), 0.0);
  EXPECT_DOUBLE_EQ(training_work_done(1800, 1800, 0.3f), 1.0);
  const double at_coarse_end = training_work_done(540, 1800, 0.3f);
  EXPECT_NEAR(at_coarse_end, 0.55 * 540 / (0.55 * 540 + 1260), 1e-12);
  EXPECT_LT(at_coarse_end, 0.3);  // a count of iterations would say 30 %
  double last = 0;
  for (int it = 10; it <= 1800; it += 10) {
    const double done = training_work_done(it, 1800, 0.3f);
    EXPECT_GT(done, last) << it;
    last = done;
  }
}

TEST(TrainingWorkDone, WithoutACoarsePhaseItCountsIterations) {
  EXPECT_DOUBLE_EQ(training_work_done(450, 1800, 0.0f), 0.25);
  EXPECT_DOUBLE_EQ(training_work_done(0, 0, 0.3f), 1.0);  // nothing to do is done
}

}  // namespace
}  // namespace chatsim::render::gs
