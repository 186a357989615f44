#pragma once
// A small layout-only scene built in code, so scene and planner tests need no shared data:
// a straight two-lane road along +x (ego lane y=0, left lane y=3.5, both forward), an oncoming
// lane at y=7, a parking lane at y=-3.5, and a crossing street at x=60 (northbound x=58.25,
// southbound x=61.75). The ego drives at 8 m/s for 5 s at 10 Hz.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "common/scene/scene.hpp"
#include "tests/support/scratch_dir.hpp"

namespace test_support {

// One 640x426 camera looking ahead from 1.5 m forward, 1.6 m up.
inline chatsim::scene::Camera front_camera() {
  chatsim::scene::Camera cam;
  cam.name = "front";
  cam.width = 640;
  cam.height = 426;
  cam.fx = cam.fy = 600;
  cam.cx = 320;
  cam.cy = 213;
  cam.sensor_to_ego.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // OpenCV camera axes in the ego FLU frame
  cam.sensor_to_ego.translation() = Eigen::Vector3d(1.5, 0, 1.6);
  return cam;
}

inline chatsim::scene::Scene synthetic_scene(bool with_lanes = true) {
  using namespace chatsim::scene;
  Scene s;
  s.name = "synthetic";
  s.source = "tests";
  s.layout_only = true;
  s.frame_rate_hz = 10;
  s.cameras.push_back(front_camera());
  for (int i = 0; i < 51; ++i) {
    Frame f;
    f.index = i;
    f.timestamp_s = 0.1 * i;
    f.ego_to_world.translation() = Eigen::Vector3d(0.8 * i, 0, 0);
    s.frames.push_back(f);
  }
  ObjectTrack parked{"parked_red", "vehicle.car", std::array<int, 3>{200, 30, 30}, {4.5, 1.9, 1.5}, {}};
  ObjectTrack mover{"moving_truck", "vehicle.truck", std::array<int, 3>{20, 20, 20}, {8, 2.5, 3}, {}};
  for (int i = 0; i < 51; ++i) {
    parked.track.push_back({i, {20, -3.5, 0.75}, 0});
    mover.track.push_back({i, {40 + 0.7 * i, 0, 1.5}, 0});
  }
  s.objects = {parked, mover};
  if (!with_lanes) return s;
  auto line = [](double x0, double y0, double x1, double y1) {
    std::vector<Eigen::Vector3d> pts;
    for (int k = 0; k <= 50; ++k) pts.emplace_back(x0 + (x1 - x0) * k / 50, y0 + (y1 - y0) * k / 50, 0);
    return pts;
  };
  std::vector<Lane> lanes;
  lanes.push_back({"ego", "driving", 3.5, line(-60, 0, 200, 0), TrafficDirection::Forward, {}});
  lanes.push_back({"left", "driving", 3.5, line(-60, 3.5, 200, 3.5), TrafficDirection::Forward, {}});
  lanes.push_back({"oncoming", "driving", 3.5, line(200, 7, -60, 7), TrafficDirection::Forward, {}});
  lanes.push_back({"parking", "parking", 2.5, line(-60, -3.5, 200, -3.5), TrafficDirection::Forward, {}});
  lanes.push_back({"north", "driving", 3.5, line(58.25, -60, 58.25, 60), TrafficDirection::Forward, {}});
  lanes.push_back({"south", "driving", 3.5, line(61.75, 60, 61.75, -60), TrafficDirection::Forward, {}});
  s.lanes = LaneMap(std::move(lanes));
  return s;
}

inline std::filesystem::path shared_commands_dir() {
  return std::filesystem::path(CHATSIM_SOURCE_DIR) / ".." / "shared" / "data" / "commands";
}

}  // namespace test_support

namespace test_support {

// The synthetic scene saved to a fresh temporary directory (for code that reads directories).
inline std::string temp_dir_for_scene() {
  const auto dir = chatsim::scratch::dir() /
                   ("chatsim-synthetic-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
  chatsim::scene::save_scene(synthetic_scene(), dir);
  return dir.string();
}

}  // namespace test_support
