// The solids a labelled vehicle casts its shadow with: a box as itself, a car as a lower body
// under a smaller greenhouse, both inside the box and turned with it.
#include <cmath>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "common/scene/objects.hpp"
#include "render/light/shadow_casters.hpp"

namespace chatsim::render::light {
namespace {

const Eigen::Vector3d kCenter(10, -3, 0.75), kSize(4.5, 1.8, 1.5);

TEST(ShadowCasters, ABoxCastsWithItsOwnCorners) {
  const GroundBox box{kCenter, kSize, 0.4, -1, false};
  const auto solids = shadow_casters(box);
  ASSERT_EQ(solids.size(), 1u);
  const auto corners = scene::box_corners(kCenter, kSize, 0.4);
  ASSERT_EQ(solids[0].size(), corners.size());
  for (size_t i = 0; i < corners.size(); ++i) EXPECT_TRUE(solids[0][i].isApprox(corners[i]));
}

TEST(ShadowCasters, ACarCastsWithALowerBodyAndAGreenhouseInsideItsBox) {
  const double yaw = 0.4;
  const GroundBox car{kCenter, kSize, yaw, -1, true};
  const auto solids = shadow_casters(car);
  ASSERT_EQ(solids.size(), 2u);
  const double ground = kCenter.z() - kSize.z() / 2;
  const Eigen::Matrix3d to_box = Eigen::AngleAxisd(-yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  double lower_top = 0, glass_top = 0, glass_bottom = 1e9, glass_front = -1e9, glass_rear = 1e9, glass_side = 0;
  for (const auto& p : solids[0]) lower_top = std::max(lower_top, p.z() - ground);
  for (const auto& p : solids[1]) {
    const Eigen::Vector3d q = to_box * (p - kCenter);  // in the box's frame: +x forward
    EXPECT_LE(std::abs(q.x()), kSize.x() / 2 + 1e-9);
    EXPECT_LE(std::abs(q.y()), kSize.y() / 2 + 1e-9);
    glass_top = std::max(glass_top, p.z() - ground), glass_bottom = std::min(glass_bottom, p.z() - ground);
    glass_front = std::max(glass_front, q.x()), glass_rear = std::min(glass_rear, q.x());
    glass_side = std::max(glass_side, std::abs(q.y()));
  }
  // The body stops at the belt line, where the glass starts; the roof is the box's top.
  EXPECT_NEAR(lower_top, 0.62 * kSize.z(), 1e-9);
  EXPECT_NEAR(glass_bottom, lower_top, 1e-9);
  EXPECT_NEAR(glass_top, kSize.z(), 1e-9);
  // The greenhouse is shorter than the car, set back from its nose, and narrower.
  EXPECT_NEAR(glass_front - glass_rear, (0.72 - 0.18) * kSize.x(), 1e-9);
  EXPECT_GT(kSize.x() / 2 - glass_front, kSize.x() / 2 + glass_rear);
  EXPECT_LT(glass_side, kSize.y() / 2);
}

}  // namespace
}  // namespace chatsim::render::light
