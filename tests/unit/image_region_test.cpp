// The area the foreground agent path traces: where a vehicle's box falls in the image.
#include <gtest/gtest.h>

#include "agents/render/image_region.hpp"

namespace chatsim::agents::render {
namespace {

scene::Camera camera() {
  scene::Camera c;
  c.width = 640, c.height = 426;
  c.fx = c.fy = 500, c.cx = 319.5, c.cy = 212.5;
  return c;
}

// A box's corners around a centre in the camera frame (camera at the origin, looking along +z).
std::vector<Eigen::Vector3d> box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < 8; ++k)
    out.push_back(centre + Eigen::Vector3d((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(), (k & 4) ? half.z() : -half.z()));
  return out;
}

TEST(ImageRegion, ABoxAheadCoversItsProjectionPadded) {
  const auto r = image_region(box({0, 0, 10}, {1, 0.5, 2}), camera(), Eigen::Isometry3d::Identity(), 8);
  // Nearest face at z = 8: x spans +-1 m -> +-62.5 px around the centre.
  EXPECT_NEAR(r.x, 319.5 - 62.5 - 8, 1.5);
  EXPECT_NEAR(r.width, 125 + 16, 2);
  EXPECT_NEAR(r.y, 212.5 - 31.25 - 8, 1.5);
}

TEST(ImageRegion, ABoxPassingBesideTheCameraIsNotTheWholeFrame) {
  // A car to the right, from 0.75 m behind the camera to 3.75 m ahead: only the right part of
  // the image can show it (its nearest visible edge, 1.1 m right at 3.75 m, is at u = 466).
  const auto r = image_region(box({2, 0, 1.5}, {0.9, 0.7, 2.25}), camera(), Eigen::Isometry3d::Identity(), 8);
  ASSERT_GT(r.area(), 0);
  EXPECT_NEAR(r.x, 466 - 8, 2);
  EXPECT_EQ(r.x + r.width, 640);
}

TEST(ImageRegion, BehindTheCameraOrOutsideTheImageIsEmpty) {
  EXPECT_EQ(image_region(box({0, 0, -10}, {1, 1, 2}), camera(), Eigen::Isometry3d::Identity()).area(), 0);
  EXPECT_EQ(image_region(box({100, 0, 10}, {1, 1, 2}), camera(), Eigen::Isometry3d::Identity()).area(), 0);
}

TEST(ImageRegion, OverlappingAreasMergeAndSeparateOnesStay) {
  const auto merged = merge_overlapping({{0, 0, 10, 10}, {100, 100, 10, 10}, {5, 5, 10, 10}, {14, 14, 90, 90}});
  ASSERT_EQ(merged.size(), 1u);  // the fourth joins the first two to the second
  EXPECT_EQ(merged[0], cv::Rect(0, 0, 110, 110));
  EXPECT_EQ(merge_overlapping({{0, 0, 10, 10}, {20, 0, 10, 10}}).size(), 2u);
}

}  // namespace
}  // namespace chatsim::agents::render
