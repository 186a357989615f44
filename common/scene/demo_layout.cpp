#include "common/scene/demo_layout.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace chatsim::scene {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Eigen::Vector3d> line(double x0, double y0, double x1, double y1, double step = 5) {
  std::vector<Eigen::Vector3d> pts;
  const int n = std::max(1, int(std::lround(std::hypot(x1 - x0, y1 - y0) / step)));
  for (int k = 0; k <= n; ++k) pts.emplace_back(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n, 0);
  return pts;
}

Camera rig_camera(const std::string& name, double yaw, const DemoOptions& o) {
  Camera c;
  c.name = name;
  c.width = o.width;
  c.height = o.height;
  c.fx = c.fy = (o.width / 2.0) / std::tan(25.0 * kPi / 180);  // 50 degree horizontal FOV
  c.cx = o.width / 2.0;
  c.cy = o.height / 2.0;
  Eigen::Matrix3d cv_in_flu;
  cv_in_flu << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // OpenCV axes (right, down, forward) in FLU
  c.sensor_to_ego.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * cv_in_flu;
  c.sensor_to_ego.translation() = Eigen::Vector3d(1.5, 0, 1.6);
  return c;
}

}  // namespace

Scene demo_layout(const DemoOptions& o) {
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> u(0, 1);
  Scene s;
  s.name = "demo-street-" + std::to_string(o.seed);
  s.source = "chatsim procedural demo (layout)";
  s.layout_only = true;
  s.frame_rate_hz = o.frame_rate_hz;
  s.ego_origin = "rear_axle";
  // Front, front-left and front-right, 40 degrees apart: 10 degrees of overlap each side.
  s.cameras = {rig_camera("front", 0, o), rig_camera("front_left", 40 * kPi / 180, o),
               rig_camera("front_right", -40 * kPi / 180, o)};
  for (int i = 0; i < o.frames; ++i) {
    Frame f;
    f.index = i;
    f.timestamp_s = i / o.frame_rate_hz;
    f.ego_to_world.translation() = Eigen::Vector3d(o.ego_speed_mps * f.timestamp_s, 0, 0);
    s.frames.push_back(f);
  }
  const double cross_x = 70;
  s.lanes = LaneMap({{"ego_lane", "driving", 3.5, line(-60, 0, 220, 0), TrafficDirection::Forward, {}},
                     {"left_lane", "driving", 3.5, line(-60, 3.5, 220, 3.5), TrafficDirection::Forward, {}},
                     {"oncoming_inner", "driving", 3.5, line(220, 7, -60, 7), TrafficDirection::Forward, {}},
                     {"oncoming_outer", "driving", 3.5, line(220, 10.5, -60, 10.5), TrafficDirection::Forward, {}},
                     {"parking_right", "parking", 2.5, line(-60, -3.25, 220, -3.25), TrafficDirection::Forward, {}},
                     {"parking_left", "parking", 2.5, line(220, 13.75, -60, 13.75), TrafficDirection::Forward, {}},
                     {"cross_northbound", "driving", 3.5, line(cross_x - 1.75, -60, cross_x - 1.75, 80),
                      TrafficDirection::Forward, {}},
                     {"cross_southbound", "driving", 3.5, line(cross_x + 1.75, 80, cross_x + 1.75, -60),
                      TrafficDirection::Forward, {}}});
  struct Kind {
    const char* category;
    Eigen::Vector3d size;
  };
  const Kind kinds[] = {{"vehicle.car", {4.6, 1.85, 1.5}}, {"vehicle.car", {4.8, 1.95, 1.75}},
                        {"vehicle.car", {5.0, 2.0, 2.1}},  {"vehicle.truck", {7.5, 2.5, 3.2}},
                        {"vehicle.bus.rigid", {12, 2.55, 3.2}}};
  const std::array<int, 3> palette[] = {{200, 25, 25},   {30, 60, 200},   {240, 240, 240}, {20, 20, 22},
                                        {175, 177, 182}, {30, 140, 50},   {240, 200, 25},  {240, 120, 20}};
  int next = 1;
  auto add = [&](const Kind& k, double x, double y, double yaw, double vx) {
    ObjectTrack t;
    t.id = "obj_" + std::to_string(next++);
    t.category = k.category;
    t.size_lwh = k.size;
    t.color_rgb = palette[size_t(u(rng) * 8) % 8];
    for (int i = 0; i < o.frames; ++i)
      t.track.push_back({i, {x + vx * s.frames[size_t(i)].timestamp_s, y, k.size.z() / 2}, yaw});
    s.objects.push_back(std::move(t));
  };
  // Parked cars on both kerbs, with gaps; never inside the crossing.
  for (double y : {-3.25, 13.75}) {
    for (double x = -20 + 12 * u(rng); x < 150; x += 7 + 14 * u(rng)) {
      if (std::abs(x - cross_x) < 10 || u(rng) < 0.35) continue;
      add(kinds[size_t(u(rng) * 3)], x, y, y > 0 ? kPi : 0, 0);
    }
  }
  // Moving traffic: one speed per lane so vehicles in a lane never meet.
  struct Flow {
    double y, speed;
  };
  for (const Flow& f : {Flow{0, 8.5}, Flow{3.5, 10}, Flow{7, -9}, Flow{10.5, -7}}) {
    double x = f.y == 0 ? 25 : -10 + 15 * u(rng);
    for (int n = 0; n < 2; ++n, x += 30 + 20 * u(rng)) {
      if (f.y == 0 && x > -8 && x < 12) continue;  // keep the ego's own spot free
      const Kind& k = kinds[size_t(u(rng) * 5)];
      add(k, x, f.y, f.speed > 0 ? 0 : kPi, f.speed);
    }
  }
  // A pedestrian on the right sidewalk, walking ahead.
  ObjectTrack ped{"obj_" + std::to_string(next++), "human.pedestrian.adult", std::nullopt, {0.6, 0.6, 1.75}, {}};
  for (int i = 0; i < o.frames; ++i)
    ped.track.push_back({i, {15 + 1.3 * s.frames[size_t(i)].timestamp_s, -6, 0.875}, 0});
  s.objects.push_back(std::move(ped));
  return s;
}

}  // namespace chatsim::scene
