// Where moving objects are in an image (what the novel-view eval's static score leaves out).
#include <gtest/gtest.h>

#include "common/scene/camera_model.hpp"
#include "render/gs/moving_mask.hpp"
#include "tests/support/synthetic_scene.hpp"

namespace chatsim::render::gs {
namespace {

// The synthetic street: a parked car at (20, -3.5), and an 8 m truck driving ahead of the ego
// from x = 40 at 7 m/s; seen by the front camera at frame 0.
bool masked(const scene::Scene& s, const cv::Mat& mask, const Eigen::Vector3d& world) {
  const auto p = scene::project(s.cameras[0], s.camera_to_world(s.frames[0], s.cameras[0]), world);
  EXPECT_TRUE(p && p->in_image);
  if (!p || !p->in_image) return false;
  return mask.at<uint8_t>(int(std::lround(p->pixel.y())), int(std::lround(p->pixel.x()))) != 0;
}

TEST(MovingMask, CoversTheMovingTruckWhereItIsAtThatTimeAndItsGroundButNotWhatStandsStill) {
  const scene::Scene s = test_support::synthetic_scene(false);
  const auto moving = moving_objects(s);
  ASSERT_EQ(moving.size(), 2u);
  EXPECT_FALSE(moving[0]);  // parked
  EXPECT_TRUE(moving[1]);
  const auto& cam = s.cameras[0];
  const auto pose = s.camera_to_world(s.frames[0], cam);
  const cv::Mat at_start = moving_object_mask(s, moving, cam, pose, 0.0);
  EXPECT_TRUE(masked(s, at_start, {40, 0, 1.5}));
  EXPECT_TRUE(masked(s, at_start, {38, -2.0, 0}));   // the ground beside it (its shadow)
  EXPECT_FALSE(masked(s, at_start, {40, -2.9, 0}));  // further off
  EXPECT_FALSE(masked(s, at_start, {20, -3.5, 0.75}));  // the parked car
  // 2.5 s later the truck is 17.5 m further on.
  const cv::Mat later = moving_object_mask(s, moving, cam, pose, 2.5);
  EXPECT_TRUE(masked(s, later, {57.5, 0, 1.5}));
  EXPECT_FALSE(masked(s, later, {38, -2.0, 0}));
  // With nothing moving there is nothing to mask.
  EXPECT_EQ(cv::countNonZero(moving_object_mask(s, {false, false}, cam, pose, 0.0)), 0);
}

}  // namespace
}  // namespace chatsim::render::gs
