#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/scene/camera_model.hpp"
#include "common/scene/scene.hpp"
#include "common/scene/scene_summary.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/synthetic_scene.hpp"

using namespace chatsim::scene;
namespace fs = std::filesystem;

namespace {

fs::path temp_path(const std::string& name) {
  return chatsim::scratch::dir() / ("chatsim-test-" + std::to_string(::getpid()) + "-" + name);
}

fs::path saved_synthetic(const std::string& name) {
  const auto dir = temp_path(name);
  fs::remove_all(dir);
  save_scene(test_support::synthetic_scene(), dir);
  return dir;
}

// Rewrites one JSON file of a scene through a function.
void edit_json(const fs::path& file, const std::function<void(nlohmann::json&)>& f) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  f(j);
  std::ofstream(file) << j.dump();
}

std::string load_error(const fs::path& dir) {
  try {
    load_scene(dir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Scene, SavesAndLoadsTheSameScene) {
  const auto dir = saved_synthetic("scene-roundtrip");
  const Scene s = load_scene(dir);
  EXPECT_EQ(s.name, "synthetic");
  EXPECT_TRUE(s.layout_only);
  ASSERT_EQ(s.frames.size(), 51u);
  EXPECT_NEAR(s.frames[10].ego_to_world.translation().x(), 8.0, 1e-9);
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.lanes.lanes().size(), 6u);
  const auto summary = summarize(s);
  EXPECT_EQ(summary["objects_by_category"]["vehicle.truck"], 1);
  EXPECT_NEAR(summary["ego_path_m"].get<double>(), 40.0, 1e-6);
}

TEST(Scene, ErrorsNameFileFieldAndProblem) {
  {
    const auto dir = saved_synthetic("scene-bad-matrix");
    edit_json(dir / "scene.json", [](nlohmann::json& j) { j["frames"][3]["ego_to_world"][0] = 2.0; });
    const auto e = load_error(dir);
    EXPECT_NE(e.find("scene.json: frames[3].ego_to_world: not a rigid transform"), std::string::npos) << e;
  }
  {
    const auto dir = saved_synthetic("scene-unknown-camera");
    edit_json(dir / "scene.json", [](nlohmann::json& j) {
      j.erase("layout_only");
      j["frames"][0]["images"] = {{"CAM_BACK", {{"path", "images/CAM_BACK/000000.jpg"}}}};
    });
    const auto e = load_error(dir);
    EXPECT_NE(e.find("frames[0].images.CAM_BACK: unknown camera 'CAM_BACK'"), std::string::npos) << e;
  }
  {
    const auto dir = saved_synthetic("scene-missing-image");
    edit_json(dir / "scene.json", [](nlohmann::json& j) {
      j.erase("layout_only");
      for (auto& f : j["frames"]) f["images"] = {{"front", {{"path", "images/front/x.jpg"}}}};
    });
    const auto e = load_error(dir);
    EXPECT_NE(e.find("frames[0].images.front.path: image file"), std::string::npos) << e;
    EXPECT_NE(e.find("does not exist"), std::string::npos) << e;
  }
  {
    const auto dir = saved_synthetic("scene-bad-object");
    edit_json(dir / "objects.json", [](nlohmann::json& j) { j["objects"][1]["track"][0]["frame"] = 999; });
    const auto e = load_error(dir);
    EXPECT_NE(e.find("objects.json: objects[1].track[0].frame: frame 999 is not in scene.json"), std::string::npos) << e;
  }
  {
    const auto dir = saved_synthetic("scene-nan");
    std::ofstream(dir / "lanes.json") << R"({"lanes": [{"id": "a", "centerline": [[0, 0, 0], [1, 0]]}]})";
    const auto e = load_error(dir);
    EXPECT_NE(e.find("lanes.json: lanes[0].centerline[1]: expected 3 numbers"), std::string::npos) << e;
  }
  {
    const auto dir = saved_synthetic("scene-escaping-path");
    edit_json(dir / "scene.json", [](nlohmann::json& j) {
      j.erase("layout_only");
      for (auto& f : j["frames"]) f["images"] = {{"front", {{"path", "../../../etc/passwd"}}}};
    });
    const auto e = load_error(dir);
    EXPECT_NE(e.find("frames[0].images.front.path: must be a path inside the scene folder"), std::string::npos) << e;
  }
  EXPECT_NE(load_error(temp_path("no-such-scene")).find("does not exist"), std::string::npos);
}

TEST(Scene, ProjectionAndUnprojectionAreInverse) {
  const Scene s = test_support::synthetic_scene();
  const auto pose = s.camera_to_world(s.frames[5], s.cameras[0]);
  const Eigen::Vector3d world(20, 1.5, 0.8);
  const auto p = project(s.cameras[0], pose, world);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->in_image);
  EXPECT_LT(p->pixel.x(), 320);  // left of centre: the point is to the ego's left
  EXPECT_NEAR(p->depth, 20 - 4 - 1.5, 1e-9);
  const Eigen::Vector3d back = unproject(s.cameras[0], pose, p->pixel, p->depth);
  EXPECT_LT((back - world).norm(), 1e-9);
  EXPECT_FALSE(project(s.cameras[0], pose, Eigen::Vector3d(-10, 0, 1)));  // behind the camera
}

TEST(Scene, LaneQueries) {
  const Scene s = test_support::synthetic_scene();
  const auto n = s.lanes.nearest({10, 3.0}, "driving");
  ASSERT_TRUE(n);
  EXPECT_EQ(s.lanes.lanes()[size_t(n->lane)].id, "left");
  EXPECT_NEAR(n->lateral, -0.5, 1e-9);
  const auto on = s.lanes.containing({30, 6.5});
  ASSERT_FALSE(on.empty());
  EXPECT_EQ(s.lanes.lanes()[size_t(on.front().lane)].id, "oncoming");
  // The oncoming lane's polyline runs toward -x: travel there is toward the ego.
  EXPECT_NEAR(std::abs(s.lanes.travel_yaw_at(on.front().lane, on.front().s)), M_PI, 1e-9);
  const auto crossings = s.lanes.crossings(s.lanes.find("ego"));
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_NEAR(s.lanes.point_at(s.lanes.find("ego"), crossings[0].s_self).x(), 58.25, 1e-6);
  EXPECT_FALSE(s.lanes.in_region({0, 0}, 4).empty());
}

TEST(Scene, ObjectBoxesInterpolateBetweenLabelledFrames) {
  ObjectTrack t{"o", "vehicle.car", std::nullopt, {4, 2, 1.5}, {{0, {0, 0, 0}, 0}, {10, {10, 0, 0}, 1.0}}};
  const auto mid = t.at(5);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->center.x(), 5, 1e-9);
  EXPECT_NEAR(mid->yaw, 0.5, 1e-9);
  EXPECT_FALSE(t.at(11));
  EXPECT_TRUE(t.has_category_prefix("vehicle"));
  EXPECT_FALSE(t.has_category_prefix("vehicle.ca"));
}

TEST(Scene, LoadsTheSharedLayoutScene) {
  const auto dir = test_support::shared_commands_dir() / "scene-layout-dev";
  if (!fs::exists(dir)) GTEST_SKIP() << "shared data absent: " << dir;
  const Scene s = load_scene(dir);
  EXPECT_EQ(s.frames.size(), 100u);
  EXPECT_EQ(s.objects.size(), 10u);
  EXPECT_EQ(s.lanes.lanes().size(), 7u);
}

// A camera that fires 12 ms after its frame sees from where the ego was then, not at the frame.
TEST(Scene, AnImageTriggeredOffTheFrameTimeIsPosedWhereTheEgoWasWhenItFired) {
  Scene s;
  Camera cam;
  cam.name = "front";
  cam.sensor_to_ego.translation() = Eigen::Vector3d(1.5, 0, 1.6);
  s.cameras = {cam};
  for (int i = 0; i < 3; ++i) {
    Frame f;
    f.index = i;
    f.timestamp_s = 0.1 * i;
    f.ego_to_world.translation() = Eigen::Vector3d(0.8 * i, 0, 0);  // 8 m/s along x
    f.ego_to_world.linear() = Eigen::AngleAxisd(0.1 * i, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    ImageRef im;
    im.path = "images/front/x.jpg";
    im.timestamp_s = f.timestamp_s + (i == 0 ? -0.012 : i == 1 ? 0.012 : 0.05);
    f.images["front"] = im;
    s.frames.push_back(f);
  }
  auto ego_x = [&](int frame) { return (s.camera_to_world(s.frames[size_t(frame)], cam) * cam.sensor_to_ego.inverse()).translation().x(); };
  EXPECT_NEAR(ego_x(1), 0.8 + 0.096, 1e-9);      // between frames 1 and 2
  EXPECT_NEAR(ego_x(0), -0.096, 1e-9);           // before frame 0: along the first step
  EXPECT_NEAR(ego_x(2), 1.6 + 0.4, 1e-9);        // after the last frame: along the last step
  const Eigen::Isometry3d mid = s.ego_to_world_at(0.15);
  EXPECT_NEAR(Eigen::AngleAxisd(mid.linear()).angle(), 0.15, 1e-9);  // rotation interpolated too
  // At the frame's own time, and with an image's own pose, nothing is interpolated.
  s.frames[1].images["front"].timestamp_s = 0.1;
  EXPECT_TRUE(s.camera_to_world(s.frames[1], cam).isApprox(s.frames[1].ego_to_world * cam.sensor_to_ego));
  Eigen::Isometry3d own = Eigen::Isometry3d::Identity();
  own.translation() = Eigen::Vector3d(5, 6, 7);
  s.frames[0].images["front"].camera_to_world = own;
  EXPECT_TRUE(s.camera_to_world(s.frames[0], cam).isApprox(own));
}

TEST(Scene, AFrameIsFoundByItsIndexNotItsPosition) {
  Scene s;
  for (int index : {10, 20, 30}) {
    Frame f;
    f.index = index;
    s.frames.push_back(f);
  }
  ASSERT_NE(s.frame(20), nullptr);
  EXPECT_EQ(s.frame(20), &s.frames[1]);
  EXPECT_EQ(s.frame(1), nullptr);
}
