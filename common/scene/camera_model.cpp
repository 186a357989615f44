#include "common/scene/camera_model.hpp"

#include <algorithm>
#include <fstream>

namespace chatsim::scene {

std::optional<Projection> project(const Camera& cam, const Eigen::Isometry3d& camera_to_world,
                                  const Eigen::Vector3d& world, double near_m) {
  const Eigen::Vector3d p = camera_to_world.inverse() * world;
  if (p.z() < near_m) return std::nullopt;
  Projection out;
  out.pixel = {cam.fx * p.x() / p.z() + cam.cx, cam.fy * p.y() / p.z() + cam.cy};
  out.depth = p.z();
  out.in_image = out.pixel.x() >= 0 && out.pixel.y() >= 0 && out.pixel.x() < cam.width && out.pixel.y() < cam.height;
  return out;
}

std::vector<Eigen::Vector2d> project_clipped(const Camera& cam, const Eigen::Isometry3d& camera_to_world,
                                             const std::vector<Eigen::Vector3d>& world, double near_m) {
  const Eigen::Isometry3d w2c = camera_to_world.inverse();
  std::vector<Eigen::Vector3d> in_front, behind;
  for (const auto& w : world) {
    const Eigen::Vector3d c = w2c * w;
    (c.z() >= near_m ? in_front : behind).push_back(c);
  }
  std::vector<Eigen::Vector3d> clipped = in_front;
  for (const auto& a : in_front)
    for (const auto& b : behind) clipped.push_back(a + (b - a) * ((a.z() - near_m) / (a.z() - b.z())));
  constexpr double kLimit = 1e5;
  std::vector<Eigen::Vector2d> px;
  for (const auto& c : clipped)
    px.emplace_back(std::clamp(cam.fx * c.x() / c.z() + cam.cx, -kLimit, kLimit),
                    std::clamp(cam.fy * c.y() / c.z() + cam.cy, -kLimit, kLimit));
  return px;
}

Eigen::Vector3d unproject(const Camera& cam, const Eigen::Isometry3d& camera_to_world, const Eigen::Vector2d& px,
                          double depth) {
  const Eigen::Vector3d p((px.x() - cam.cx) / cam.fx * depth, (px.y() - cam.cy) / cam.fy * depth, depth);
  return camera_to_world * p;
}

std::vector<LidarPoint> read_lidar(const std::filesystem::path& file, int stride) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(file, "", "cannot open the LiDAR file");
  std::vector<float> raw;
  in.seekg(0, std::ios::end);
  const auto bytes = size_t(in.tellg());
  in.seekg(0);
  if (bytes % (sizeof(float) * size_t(stride)) != 0)
    throw SceneError(file, "", "size " + std::to_string(bytes) + " bytes is not a whole number of points of " +
                                   std::to_string(stride) + " float32 values");
  raw.resize(bytes / sizeof(float));
  in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(bytes));
  std::vector<LidarPoint> out(raw.size() / size_t(stride));
  for (size_t i = 0; i < out.size(); ++i) {
    const float* r = &raw[i * size_t(stride)];
    out[i] = {Eigen::Vector3f(r[0], r[1], r[2]), r[3]};
  }
  return out;
}

}  // namespace chatsim::scene
