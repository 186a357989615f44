// The progress line that logs (not a terminal) get: what, elapsed time and, once it can be told, the ETA.
#include <gtest/gtest.h>

#include "common/util/progress.hpp"

TEST(Progress, LogLineTellsElapsedAndTimeLeft) {
  EXPECT_EQ(chatsim::progress_log_line("train", 0.4, "iteration 600", 116), "train:  40% iteration 600 (116s elapsed, ETA 174s)");
}

TEST(Progress, NoEtaBeforeOnePercentOrWhenDone) {
  EXPECT_EQ(chatsim::progress_log_line("train", 0.005, "starting", 3), "train:   0% starting (3s elapsed)");
  EXPECT_EQ(chatsim::progress_log_line("train", 1.0, "done", 290), "train: 100% done (290s elapsed)");
  EXPECT_LT(chatsim::progress_eta_s(0.0, 10), 0);
  EXPECT_DOUBLE_EQ(chatsim::progress_eta_s(0.5, 10), 10);
}
