// Where moving objects are in an image (what the novel-view eval's static score leaves out).
#include <gtest/gtest.h>

#include "common/scene/camera_model.hpp"
#include "render/gs/moving_mask.hpp"

namespace chatsim::render::gs {
namespace {

// One camera 1.5 m up looking along +x; a car crossing 12 m ahead from right to left, a cone
// standing still beside its path.
struct Crossing {
  scene::Scene scene;
  scene::Camera cam;

  Crossing() {
    cam.name = "front";
    cam.width = 320, cam.height = 200;
    cam.fx = cam.fy = 400, cam.cx = 159.5, cam.cy = 99.5;
    Eigen::Matrix3d r;
    r << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // OpenCV camera axes in the ego's FLU frame
    cam.sensor_to_ego.linear() = r;
    cam.sensor_to_ego.translation() = Eigen::Vector3d(0, 0, 1.5);
    scene.cameras.push_back(cam);
    for (int f = 0; f < 3; ++f) {
      scene::Frame fr;
      fr.index = f, fr.timestamp_s = 0.1 * f;
      scene.frames.push_back(fr);
    }
    scene::ObjectTrack car;
    car.id = "car", car.size_lwh = {4, 1.8, 1.5};
    for (int f = 0; f < 3; ++f) car.track.push_back({f, Eigen::Vector3d(12, -4 + 4 * f, 0.75), M_PI / 2});
    scene::ObjectTrack cone;
    cone.id = "cone", cone.size_lwh = {0.5, 0.5, 0.8};
    for (int f = 0; f < 3; ++f) cone.track.push_back({f, Eigen::Vector3d(12, 4, 0.4), 0});
    scene.objects = {car, cone};
  }

  bool masked(const cv::Mat& mask, const Eigen::Vector3d& world) const {
    const auto p = scene::project(cam, scene.camera_to_world(scene.frames[0], cam), world);
    EXPECT_TRUE(p && p->in_image);
    return mask.at<uint8_t>(int(std::lround(p->pixel.y())), int(std::lround(p->pixel.x()))) != 0;
  }
};

TEST(MovingMask, CoversTheMovingCarWhereItIsAtThatTimeAndItsGroundButNotWhatStandsStill) {
  const Crossing c;
  const auto moving = moving_objects(c.scene);
  ASSERT_EQ(moving.size(), 2u);
  EXPECT_TRUE(moving[0]);
  EXPECT_FALSE(moving[1]);
  const auto pose = c.scene.camera_to_world(c.scene.frames[0], c.cam);
  const cv::Mat at_start = moving_object_mask(c.scene, moving, c.cam, pose, 0.0);
  // The car is 4 m long along y: at the start it spans y in [-6, -2].
  EXPECT_TRUE(c.masked(at_start, {12, -4, 0.75}));
  EXPECT_TRUE(c.masked(at_start, {12, -2 + 0.8, 0.0}));   // the ground beside it (its shadow)
  EXPECT_FALSE(c.masked(at_start, {12, -2 + 1.4, 0.0}));  // further off
  EXPECT_FALSE(c.masked(at_start, {12, 4, 0.4}));               // the cone
  // Between frames the box is where the track puts it then.
  const cv::Mat later = moving_object_mask(c.scene, moving, c.cam, pose, 0.15);
  EXPECT_TRUE(c.masked(later, {12, 2, 0.75}));
  EXPECT_FALSE(c.masked(later, {12, -4, 1.2}));
  // With nothing moving there is nothing to mask.
  EXPECT_EQ(cv::countNonZero(moving_object_mask(c.scene, {false, false}, c.cam, pose, 0.0)), 0);
}

}  // namespace
}  // namespace chatsim::render::gs
