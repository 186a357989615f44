// Which Gaussians training keeps out of the camera pose's gradient: the ground where a moving
// object's shadow travels with it (the synthetic street's truck), and nothing else.
#include <cmath>

#include <gtest/gtest.h>

#include "render/gs/moving_mask.hpp"
#include "render/gs/trainer.hpp"
#include "tests/support/synthetic_scene.hpp"

namespace chatsim::render::gs {
namespace {

// The truck is 8 x 2.5 x 3 m, standing on z = 0, at x = 40 + 7 t (m, t in s); the parked car
// stands at (20, -3.5).
// Placed in reverse order of the model's (source), so that owners are looked up through it.
struct Placed {
  Gaussians g;
  std::vector<int> owner, source;
  void add(const Eigen::Vector3f& p, int own = -1) {
    g.add(p, 0.1f, Eigen::Vector3f::Zero(), 0.5f);
    owner.insert(owner.begin(), own);
    for (int& i : source) ++i;
    source.push_back(0);
  }
  std::vector<uint8_t> band(const scene::Scene& s, double time_s, double pad_m) const {
    return moving_shadow_band(s, moving_objects(s), g, source, owner, time_s, pad_m);
  }
};

TEST(GsPoseBlind, TheGroundAroundAMovingObjectAtThatTimeAndNothingElse) {
  const scene::Scene s = test_support::synthetic_scene(false);
  Placed p;
  p.add({54, 0, 0.1f});        // 0: 3 m ahead of the truck at t = 1 s, on the ground
  p.add({47, 4.75f, 0});       // 1: 3.5 m beside it
  p.add({56, 0, 0});           // 2: 5 m ahead of its front: beyond the 4 m pad
  p.add({47, 0, 2});           // 3: in the air (the truck's side, not the ground)
  p.add({20, -1.5f, 0});       // 4: beside the parked car
  p.add({54, 0, 0.1f}, 1);     // 5: the truck's own Gaussian
  const auto at_1s = p.band(s, 1.0, 4.0);
  ASSERT_EQ(at_1s.size(), 6u);
  EXPECT_TRUE(at_1s[0]);
  EXPECT_TRUE(at_1s[1]);
  EXPECT_FALSE(at_1s[2]);
  EXPECT_FALSE(at_1s[3]);
  EXPECT_FALSE(at_1s[4]);
  EXPECT_FALSE(at_1s[5]);
  // The band moves with the truck: at t = 0 it ends at x = 48.
  EXPECT_FALSE(p.band(s, 0.0, 4.0)[0]);
  // A narrower pad leaves out less.
  EXPECT_FALSE(p.band(s, 1.0, 1.0)[0]);
}

TEST(GsPoseBlind, TheBandTurnsWithTheObject) {
  scene::Scene s = test_support::synthetic_scene(false);
  for (auto& point : s.objects[1].track) point.yaw = M_PI / 2;  // the truck turned across the road
  Placed p;
  p.add({54, 0, 0.1f});    // 0: 3 m ahead of the straight truck's front; 7 m off the turned one's side
  p.add({47, 7.5f, 0.1f});  // 1: 3.5 m beyond the turned truck's front; 7.5 m beside the straight one
  const auto turned = p.band(s, 1.0, 4.0);
  EXPECT_FALSE(turned[0]);
  EXPECT_TRUE(turned[1]);
  const auto straight = p.band(test_support::synthetic_scene(false), 1.0, 4.0);
  EXPECT_TRUE(straight[0]);
  EXPECT_FALSE(straight[1]);
}

}  // namespace
}  // namespace chatsim::render::gs
