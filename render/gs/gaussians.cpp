#include "render/gs/gaussians.hpp"

#include <algorithm>
#include <cmath>

namespace chatsim::render::gs {

void Gaussians::add(const Eigen::Vector3f& pos, float sigma, const Eigen::Vector3f& log_radiance, float opacity) {
  const size_t i = size();
  resize(i + 1);
  float* g = at(i);
  g[kPosX] = pos.x(), g[kPosY] = pos.y(), g[kPosZ] = pos.z();
  g[kScaleX] = g[kScaleY] = g[kScaleZ] = std::log(std::max(sigma, 1e-4f));
  g[kRotW] = 1, g[kRotX] = g[kRotY] = g[kRotZ] = 0;
  g[kOpacity] = logit(std::clamp(opacity, 1e-4f, 1 - 1e-4f));
  for (int c = 0; c < 3; ++c) {
    g[kColor + 4 * c] = log_radiance[c];
    g[kColor + 4 * c + 1] = g[kColor + 4 * c + 2] = g[kColor + 4 * c + 3] = 0;
  }
}

}  // namespace chatsim::render::gs
