#pragma once
// The radiance field's primitives: 3D Gaussians (position, scale, rotation, opacity) carrying
// HDR radiance in log space with a linear dependence on the view direction, stored as
// structure-of-arrays so the rasteriser and the optimiser stream through them.
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace chatsim::render::gs {

// Parameters per Gaussian, in optimiser order.
enum Param : int {
  kPosX, kPosY, kPosZ,                 // world position (m)
  kScaleX, kScaleY, kScaleZ,           // log of the standard deviations (m)
  kRotW, kRotX, kRotY, kRotZ,          // quaternion (normalised on use)
  kOpacity,                            // logit of the peak opacity
  kColor,                              // 12 values: per channel log radiance c0 + c . view_dir
  kParamCount = kColor + 12
};

struct Gaussians {
  std::vector<float> p;   // size() * kParamCount, Gaussian-major

  size_t size() const { return p.size() / kParamCount; }
  float* at(size_t i) { return &p[i * kParamCount]; }
  const float* at(size_t i) const { return &p[i * kParamCount]; }
  void resize(size_t n) { p.resize(n * kParamCount, 0.0f); }

  // Appends a round Gaussian with radiance `log_radiance` (per channel) seen from everywhere.
  void add(const Eigen::Vector3f& position, float sigma, const Eigen::Vector3f& log_radiance, float opacity);
};

inline float sigmoid(float x) { return 1.0f / (1.0f + std::exp(-x)); }
inline float logit(float p) { return std::log(p / (1 - p)); }

}  // namespace chatsim::render::gs
