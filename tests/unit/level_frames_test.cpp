// Levelling frames by static boxes (level_frames.hpp): a rig whose recorded poses lost their
// height and tilt is recovered from the boxes it labelled, which then stay put.
#include <gtest/gtest.h>

#include <random>

#include "common/import/level_frames.hpp"

using namespace chatsim;

namespace {

// What the recorded poses missed at each frame (frame 0: nothing, the world's origin).
import::FrameLevel truth_at(int frame) { return {0.12 * frame - 0.01 * frame * frame, 0.004 * frame, -0.002 * frame, 0}; }

double lift(const import::FrameLevel& l, const Eigen::Vector3d& ego, const Eigen::Vector3d& at) {
  return l.height + l.slope_x * (at.x() - ego.x()) + l.slope_y * (at.y() - ego.y());
}

// Ten frames driving 2 m each along x; twelve parked cars on both sides; one moving car. Boxes
// are recorded as the unlevelled rig saw them: lowered by the lift its frame missed. Frame 7
// sees only three of the parked cars.
scene::Scene recorded_scene() {
  scene::Scene s;
  for (int f = 0; f < 10; ++f) {
    scene::Frame fr;
    fr.index = f;
    fr.timestamp_s = 0.5 * f;
    fr.ego_to_world.translation() = Eigen::Vector3d(2.0 * f, 0, 0);
    s.frames.push_back(fr);
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> along(-10, 30), height(-0.5, 1.5);
  for (int k = 0; k < 12; ++k) {
    scene::ObjectTrack o;
    o.id = "parked_" + std::to_string(k);
    o.category = "vehicle.car";
    o.size_lwh = {4.5, 1.8, 1.5};
    const Eigen::Vector3d at(along(rng), (k % 2 ? 1 : -1) * (4 + k), height(rng));
    for (const auto& fr : s.frames) {
      if (fr.index == 7 && k >= 3) continue;
      const Eigen::Vector3d ego = fr.ego_to_world.translation();
      o.track.push_back({fr.index, at - Eigen::Vector3d(0, 0, lift(truth_at(fr.index), ego, at)), 0.3});
    }
    s.objects.push_back(o);
  }
  scene::ObjectTrack moving;
  moving.id = "moving";
  moving.category = "vehicle.car";
  for (const auto& fr : s.frames) moving.track.push_back({fr.index, Eigen::Vector3d(3.0 * fr.index, 3, 5.0 * (fr.index % 2)), 0});
  s.objects.push_back(moving);
  return s;
}

}  // namespace

TEST(LevelFrames, RecoversTheHeightAndTiltTheRecordedPosesMissed) {
  const scene::Scene s = recorded_scene();
  const auto levels = import::fit_frame_levels(s);
  ASSERT_EQ(levels.size(), 10u);
  for (const auto& [frame, l] : levels) {
    const auto t = truth_at(frame);
    // Frame 7 is interpolated: the truth's curvature (0.01 m per frame squared) is missed there.
    EXPECT_NEAR(l.height, t.height, frame == 7 ? 0.03 : 0.01) << "frame " << frame;
    EXPECT_NEAR(l.slope_x, t.slope_x, 1e-3) << "frame " << frame;
    EXPECT_NEAR(l.slope_y, t.slope_y, 1e-3) << "frame " << frame;
  }
  EXPECT_EQ(levels.at(7).objects, 0) << "three cars are too few: interpolated";
  EXPECT_EQ(levels.at(3).objects, 12);
}

TEST(LevelFrames, AppliedTheParkedCarsStayPutAndTheRigRises) {
  scene::Scene s = recorded_scene();
  import::apply_frame_levels(s, import::fit_frame_levels(s));
  for (const auto& o : s.objects) {
    if (o.id == "moving") continue;
    double lo = 1e9, hi = -1e9;
    for (const auto& p : o.track)
      if (p.frame != 7) lo = std::min(lo, p.center.z()), hi = std::max(hi, p.center.z());  // 7: interpolated
    EXPECT_LT(hi - lo, 0.02) << o.id;
  }
  for (const auto& f : s.frames)
    EXPECT_NEAR(f.ego_to_world.translation().z(), truth_at(f.index).height, f.index == 7 ? 0.03 : 0.01) << "frame " << f.index;
  EXPECT_LT(s.frames[0].ego_to_world.translation().norm(), 1e-9) << "the world stays the first ego pose";
}

TEST(LevelFrames, TooFewStaticBoxesLeaveTheSceneAsItIs) {
  scene::Scene s = recorded_scene();
  s.objects.resize(4);  // four parked cars: no frame has six
  EXPECT_TRUE(import::fit_frame_levels(s).empty());
}
