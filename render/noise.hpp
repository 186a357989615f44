#pragma once
// Deterministic value noise for procedural textures: the same point always gets the same value.
#include <cmath>
#include <cstdint>

#include <Eigen/Core>

#include "render/sampling.hpp"

namespace chatsim::render {

// A hash of integer lattice coordinates to [0, 1).
inline float lattice_value(int x, int y, int z, uint64_t seed) {
  // One mix of a combined key: textures evaluate this millions of times per image.
  const uint64_t key = (uint64_t(uint32_t(x)) * 0x9E3779B97F4A7C15ULL) ^ (uint64_t(uint32_t(y)) * 0xC2B2AE3D27D4EB4FULL) ^
                       (uint64_t(uint32_t(z)) * 0x165667B19E3779F9ULL) ^ seed;
  const uint64_t h = mix64(key);
  return float(h >> 40) * (1.0f / 16777216.0f);
}

// Smooth value noise in [0, 1).
inline float value_noise(const Eigen::Vector3f& p, uint64_t seed) {
  const float fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
  const int x = int(fx), y = int(fy), z = int(fz);
  auto fade = [](float t) { return t * t * (3 - 2 * t); };
  const float u = fade(p.x() - fx), v = fade(p.y() - fy), w = fade(p.z() - fz);
  auto L = [&](int dx, int dy, int dz) { return lattice_value(x + dx, y + dy, z + dz, seed); };
  const float x00 = L(0, 0, 0) + u * (L(1, 0, 0) - L(0, 0, 0));
  const float x10 = L(0, 1, 0) + u * (L(1, 1, 0) - L(0, 1, 0));
  const float x01 = L(0, 0, 1) + u * (L(1, 0, 1) - L(0, 0, 1));
  const float x11 = L(0, 1, 1) + u * (L(1, 1, 1) - L(0, 1, 1));
  const float y0 = x00 + v * (x10 - x00), y1 = x01 + v * (x11 - x01);
  return y0 + w * (y1 - y0);
}

// Fractal sum of octaves, centred on 0 (about -0.5 .. 0.5).
inline float fbm(const Eigen::Vector3f& p, uint64_t seed, int octaves = 3) {
  float sum = 0, amp = 0.5f, norm = 0;
  Eigen::Vector3f q = p;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * (value_noise(q, seed + uint64_t(i)) - 0.5f);
    norm += amp;
    amp *= 0.5f;
    q *= 2.03f;
  }
  return sum / norm;
}

}  // namespace chatsim::render
