// The nuScenes importer on the shared scene-0916 (skipped without it): frames, per-image poses
// consistent with the rig, and boxes that land on the vehicles (checked with LiDAR points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "common/import/nuscenes_import.hpp"
#include "common/scene/camera_model.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim;
namespace fs = std::filesystem;

namespace {

fs::path dataroot() { return test_support::shared_commands_dir().parent_path() / "nuscenes-scene-0916"; }

// Imported once for all tests here.
const scene::Scene& imported() {
  static const scene::Scene s = [] {
    import::NuScenesOptions o;
    o.dataroot = dataroot();
    const auto out = chatsim::scratch::dir() / ("chatsim-nuscenes-" + std::to_string(::getpid()));
    import::import_nuscenes(o, out);
    return scene::load_scene(out);  // what we wrote must load and validate
  }();
  return s;
}


}  // namespace

TEST(NuScenesImport, FramesCamerasAndDerivedLanes) {
  if (!fs::exists(dataroot())) GTEST_SKIP() << "shared data absent: " << dataroot();
  const auto& s = imported();
  EXPECT_EQ(s.frames.size(), 41u);
  ASSERT_EQ(s.cameras.size(), 3u);
  EXPECT_EQ(s.cameras[0].name, "CAM_FRONT");
  for (const auto& f : s.frames) EXPECT_EQ(f.images.size(), 3u);
  EXPECT_EQ(s.lanes_source, "derived_from_ego_path");
  EXPECT_EQ(s.lanes.lanes().size(), 3u);
  // The world is the ego at frame 0.
  EXPECT_LT(s.frames[0].ego_to_world.translation().norm(), 1e-6);
  EXPECT_GT(s.objects.size(), 50u);
  int colored = 0;
  for (const auto& o : s.objects) colored += o.color_rgb ? 1 : 0;
  EXPECT_GT(colored, 30);
}

// Each image keeps its own ego pose; it differs from the frame's by the motion between triggers.
TEST(NuScenesImport, PerImagePosesAreConsistentWithTheRig) {
  if (!fs::exists(dataroot())) GTEST_SKIP() << "shared data absent: " << dataroot();
  const auto& s = imported();
  double largest = 0;
  bool any_differs = false;
  for (const auto& f : s.frames)
    for (const auto& cam : s.cameras) {
      const auto& img = f.images.at(cam.name);
      ASSERT_TRUE(img.camera_to_world);
      const Eigen::Isometry3d rig = f.ego_to_world * cam.sensor_to_ego;
      const double d = (img.camera_to_world->translation() - rig.translation()).norm();
      largest = std::max(largest, d);
      any_differs = any_differs || d > 1e-3;
      EXPECT_LT(std::abs(img.timestamp_s - f.timestamp_s), 0.1);
    }
  EXPECT_LT(largest, 1.0);  // at parking-lot speeds, under a metre between triggers
  EXPECT_TRUE(any_differs);
}

// LiDAR points inside a vehicle's box project inside that box's image footprint: boxes,
// LiDAR and camera calibration all agree.
TEST(NuScenesImport, BoxesLandOnTheVehiclesPixels) {
  if (!fs::exists(dataroot())) GTEST_SKIP() << "shared data absent: " << dataroot();
  const auto& s = imported();
  int checked = 0;
  for (size_t fi = 0; fi < s.frames.size() && checked < 12; fi += 5) {
    const auto& f = s.frames[fi];
    const auto pts = scene::read_lidar(s.dir / f.lidar, 4);
    for (const auto& o : s.objects) {
      if (!o.has_category_prefix("vehicle.car")) continue;
      const auto box = o.at(int(fi));
      if (!box) continue;
      const Eigen::Isometry3d world_to_box =
          (Eigen::Translation3d(box->center) * Eigen::AngleAxisd(box->yaw, Eigen::Vector3d::UnitZ())).inverse();
      std::vector<Eigen::Vector3d> in_box;
      for (const auto& p : pts) {
        const Eigen::Vector3d w = f.ego_to_world * p.xyz.cast<double>();
        const Eigen::Vector3d b = world_to_box * w;
        if (std::abs(b.x()) < o.size_lwh.x() / 2 && std::abs(b.y()) < o.size_lwh.y() / 2 && std::abs(b.z()) < o.size_lwh.z() / 2)
          in_box.push_back(w);
      }
      if (in_box.size() < 30) continue;
      const auto& cam = s.cameras[0];
      const auto pose = s.camera_to_world(f, cam);
      double u0 = 1e9, v0 = 1e9, u1 = -1e9, v1 = -1e9;
      bool visible = true;
      for (const auto& c : scene::box_corners(box->center, o.size_lwh, box->yaw)) {
        const auto pr = scene::project(cam, pose, c, 1.0);
        if (!pr || !pr->in_image) visible = false;
        if (!pr) break;
        u0 = std::min(u0, pr->pixel.x()), v0 = std::min(v0, pr->pixel.y());
        u1 = std::max(u1, pr->pixel.x()), v1 = std::max(v1, pr->pixel.y());
      }
      if (!visible) continue;
      int hits = 0;
      for (const auto& w : in_box) {
        const auto pr = scene::project(cam, pose, w, 1.0);
        // A few pixels of slack for the time between the LiDAR sweep and the camera trigger.
        hits += pr && pr->pixel.x() > u0 - 8 && pr->pixel.x() < u1 + 8 && pr->pixel.y() > v0 - 8 && pr->pixel.y() < v1 + 8;
      }
      EXPECT_GT(double(hits) / double(in_box.size()), 0.95) << o.id << " frame " << fi;
      ++checked;
    }
  }
  EXPECT_GE(checked, 3);
}

// nuScenes' ego poses all lie at height 0; levelled by the static boxes, the LiDAR sweeps (not
// used by that fit) agree on the ground's height: the lowest return per square metre, 3-25 m
// from the rig, of frames four apart (about 9 m of travel). Unlevelled, they differ by 0.25 m
// in the median (up to 0.51); levelled, about 0.03 (up to 0.08).
TEST(NuScenesImport, LevelledFramesAgreeOnTheGroundsHeight) {
  if (!fs::exists(dataroot())) GTEST_SKIP() << "shared data absent: " << dataroot();
  const auto& s = imported();
  std::vector<std::map<std::pair<int, int>, double>> lowest;
  for (const auto& f : s.frames) {
    auto& cells = lowest.emplace_back();
    for (const auto& p : scene::read_lidar(s.dir / f.lidar)) {
      const double r = p.xyz.head<2>().norm();
      if (r < 3 || r > 25) continue;
      const Eigen::Vector3d w = f.ego_to_world * p.xyz.cast<double>();
      const std::pair<int, int> cell{int(std::floor(w.x())), int(std::floor(w.y()))};
      const auto [it, fresh] = cells.try_emplace(cell, w.z());
      if (!fresh) it->second = std::min(it->second, w.z());
    }
  }
  std::vector<double> offsets;
  for (size_t i = 0; i + 4 < lowest.size(); ++i) {
    std::vector<double> d;
    for (const auto& [cell, z] : lowest[i])
      if (const auto it = lowest[i + 4].find(cell); it != lowest[i + 4].end()) d.push_back(it->second - z);
    if (d.size() < 20) continue;
    std::nth_element(d.begin(), d.begin() + long(d.size() / 2), d.end());
    offsets.push_back(std::abs(d[d.size() / 2]));
  }
  ASSERT_GT(offsets.size(), 20u);
  std::sort(offsets.begin(), offsets.end());
  EXPECT_LT(offsets[offsets.size() / 2], 0.08);
  EXPECT_LT(offsets.back(), 0.2);
}

TEST(NuScenesImport, UnknownSceneAndCameraAreClearErrors) {
  if (!fs::exists(dataroot())) GTEST_SKIP() << "shared data absent: " << dataroot();
  import::NuScenesOptions o;
  o.dataroot = dataroot();
  o.scene = "scene-9999";
  try {
    import::import_nuscenes(o, chatsim::scratch::dir() / "chatsim-never");
    FAIL();
  } catch (const import::ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("scene-0916"), std::string::npos) << e.what();  // lists what exists
  }
  o.scene = "scene-0916";
  o.cameras = {"CAM_UPSIDE_DOWN"};
  EXPECT_THROW(import::import_nuscenes(o, chatsim::scratch::dir() / "chatsim-never"), import::ImportError);
  o.dataroot = "/nonexistent";
  EXPECT_THROW(import::import_nuscenes(o, chatsim::scratch::dir() / "chatsim-never"), import::ImportError);
}

