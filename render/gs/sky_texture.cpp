#include "render/gs/sky_texture.hpp"

#include <cmath>

#include "render/equirect.hpp"

namespace chatsim::render::gs {

SkyTexture::SkyTexture(int width, int height, float log_radiance)
    : w_(width), h_(height), texels_(size_t(width) * size_t(height) * 3, log_radiance) {}

SkyTexture::Taps SkyTexture::taps(const Eigen::Vector3f& d) const {
  const Eigen::Vector2f uv = equirect_uv(d);
  const float fx = uv.x() * float(w_) - 0.5f, fy = uv.y() * float(h_) - 0.5f;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float ax = fx - float(x0), ay = fy - float(y0);
  Taps t;
  auto idx = [&](int x, int y) {
    x = ((x % w_) + w_) % w_;
    y = std::clamp(y, 0, h_ - 1);
    return y * w_ + x;
  };
  t.index[0] = idx(x0, y0), t.weight[0] = (1 - ax) * (1 - ay);
  t.index[1] = idx(x0 + 1, y0), t.weight[1] = ax * (1 - ay);
  t.index[2] = idx(x0, y0 + 1), t.weight[2] = (1 - ax) * ay;
  t.index[3] = idx(x0 + 1, y0 + 1), t.weight[3] = ax * ay;
  return t;
}

Eigen::Vector3f SkyTexture::radiance(const Taps& t) const {
  // Interpolated in log space, then exponentiated: positive and smooth.
  Eigen::Vector3f l = Eigen::Vector3f::Zero();
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) l[c] += t.weight[k] * texels_[size_t(t.index[k]) * 3 + size_t(c)];
  return l.array().exp();
}

Eigen::Vector3f SkyTexture::radiance(const Eigen::Vector3f& d) const { return radiance(taps(d)); }

void SkyTexture::backward(const Taps& t, const Eigen::Vector3f& g, const Eigen::Vector3f& rad, float* grad) const {
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) grad[size_t(t.index[k]) * 3 + size_t(c)] += g[c] * rad[c] * t.weight[k];
}

}  // namespace chatsim::render::gs
