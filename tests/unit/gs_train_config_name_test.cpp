// The benchmark's one-word training configurations: each part of the name sets its option,
// switches come off the end only, and a bad name is refused with what to write instead.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "render/gs/train_config_name.hpp"

namespace chatsim::render::gs {
namespace {

std::string error_of(const std::string& name) {
  try {
    parse_train_config_name(name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(TrainConfigName, EachPartSetsItsOption) {
  TrainOptions base;
  base.holdout = 8;
  base.max_width = 800;
  const TrainOptions plain = parse_train_config_name("fast", base);
  EXPECT_EQ(plain.preset, "fast");
  EXPECT_EQ(plain.max_iterations, 0);
  EXPECT_TRUE(plain.exposure);
  EXPECT_TRUE(plain.pose_refinement);
  EXPECT_EQ(plain.ssim_weight, 0.0f);
  EXPECT_FLOAT_EQ(plain.coarse_share, TrainOptions{}.coarse_share);
  EXPECT_EQ(plain.holdout, 8);
  EXPECT_EQ(plain.max_width, 800);

  const TrainOptions all = parse_train_config_name("quality-600-no-exposure-no-pose-refinement-dssim-coarse", base);
  EXPECT_EQ(all.preset, "quality");
  EXPECT_EQ(all.max_iterations, 600);
  EXPECT_FALSE(all.exposure);
  EXPECT_FALSE(all.pose_refinement);
  EXPECT_FLOAT_EQ(all.ssim_weight, 0.2f);
  EXPECT_FLOAT_EQ(all.coarse_share, kCoarseConfigShare);
  EXPECT_NE(kCoarseConfigShare, TrainOptions{}.coarse_share);

  // Switches in another order mean the same.
  const TrainOptions swapped = parse_train_config_name("draft-dssim-no-exposure");
  EXPECT_EQ(swapped.preset, "draft");
  EXPECT_FALSE(swapped.exposure);
  EXPECT_TRUE(swapped.pose_refinement);
  EXPECT_FLOAT_EQ(swapped.ssim_weight, 0.2f);
}

TEST(TrainConfigName, BadNamesAreRefusedWithTheFix) {
  EXPECT_NE(error_of("ultra-600").find("unknown preset 'ultra', use draft, fast or quality"), std::string::npos);
  EXPECT_NE(error_of("fast-abc").find("'abc' is neither an iteration count"), std::string::npos);
  EXPECT_NE(error_of("fast-0").find("'0' is neither"), std::string::npos);
  EXPECT_NE(error_of("fast-").find("config 'fast-'"), std::string::npos);
  // A switch inside the name, not at its end, is not taken for one.
  EXPECT_NE(error_of("fast-dssim-600").find("'dssim-600' is neither"), std::string::npos);
  EXPECT_NE(error_of("fast-600-dssim-dssim").find("is neither"), std::string::npos);
  EXPECT_NE(error_of("fast-coarse-600").find("'coarse-600' is neither"), std::string::npos);
  EXPECT_EQ(error_of("fast-600"), "");
  EXPECT_NE(error_of("-dssim").find("unknown preset ''"), std::string::npos);
}

}  // namespace
}  // namespace chatsim::render::gs
