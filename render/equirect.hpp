#pragma once
// The equirectangular mapping of SCENE_FORMAT.md's sky files: u = 0.5 faces +x of the world,
// u grows toward -y (to the right, seen from inside), v = 0 is +z (zenith), v = 1 is -z.
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "render/sampling.hpp"

namespace chatsim::render {

inline constexpr const char* kEquirectMapping = "equirect: u=0.5 faces +x of the world, v=0 is +z";

inline Eigen::Vector2f equirect_uv(const Eigen::Vector3f& d) {
  const float phi = std::atan2(d.y(), d.x());
  float u = 0.5f - phi / (2 * kPi);
  if (u < 0) u += 1;
  if (u >= 1) u -= 1;
  return {u, std::acos(std::clamp(d.z(), -1.0f, 1.0f)) / kPi};
}

inline Eigen::Vector3f equirect_dir(float u, float v) {
  const float phi = (0.5f - u) * 2 * kPi;
  const float theta = v * kPi;
  const float s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

}  // namespace chatsim::render
