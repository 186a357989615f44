#include "render/sky.hpp"

#include <algorithm>
#include <cmath>

#include "render/equirect.hpp"
#include "render/sampling.hpp"

namespace chatsim::render {

float sun_cos_half_angle() { return std::cos(kSunHalfAngleRad); }
float sun_solid_angle_sr() { return cone_solid_angle(sun_cos_half_angle()); }

namespace {

float perez(const float c[5], float cos_theta, float gamma) {
  const float ct = std::max(cos_theta, 0.01f);
  const float cg = std::cos(gamma);
  return (1 + c[0] * std::exp(c[1] / ct)) * (1 + c[2] * std::exp(c[3] * gamma) + c[4] * cg * cg);
}

Rgb xyY_to_linear_srgb(float x, float y, float Y) {
  if (y <= 1e-6f) return Rgb::Zero();
  const float X = x / y * Y, Z = (1 - x - y) / y * Y;
  return Rgb(3.2406f * X - 1.5372f * Y - 0.4986f * Z, -0.9689f * X + 1.8758f * Y + 0.0415f * Z,
             0.0557f * X - 0.2040f * Y + 1.0570f * Z)
      .cwiseMax(0.0f);
}

}  // namespace

Sky::Sky(const SkyParams& params) : p_(params), sun_(params.sun_direction.normalized()) {
  const float T = std::clamp(p_.turbidity, 1.7f, 10.0f);
  // Below the horizon the sun still shapes the sky's colours; the formulas want theta_s <= 90.
  theta_s_ = std::acos(std::clamp(sun_.z(), 0.0f, 1.0f));
  const float ts = theta_s_, ts2 = ts * ts, ts3 = ts2 * ts;
  const float chi = (4.0f / 9.0f - T / 120.0f) * (kPi - 2 * ts);
  const float Yz = std::max(0.0f, (4.0453f * T - 4.9710f) * std::tan(chi) - 0.2155f * T + 2.4192f);
  const float xz = T * T * (0.00166f * ts3 - 0.00375f * ts2 + 0.00209f * ts) +
                   T * (-0.02903f * ts3 + 0.06377f * ts2 - 0.03202f * ts + 0.00394f) +
                   (0.11693f * ts3 - 0.21196f * ts2 + 0.06052f * ts + 0.25886f);
  const float yz = T * T * (0.00275f * ts3 - 0.00610f * ts2 + 0.00317f * ts) +
                   T * (-0.04214f * ts3 + 0.08970f * ts2 - 0.04153f * ts + 0.00516f) +
                   (0.15346f * ts3 - 0.26756f * ts2 + 0.06670f * ts + 0.26688f);
  zenith_xyY_ = {xz, yz, Yz};
  const float c[3][5] = {{0.1787f * T - 1.4630f, -0.3554f * T + 0.4275f, -0.0227f * T + 5.3251f,
                          0.1206f * T - 2.5771f, -0.0670f * T + 0.3703f},
                         {-0.0193f * T - 0.2592f, -0.0665f * T + 0.0008f, -0.0004f * T + 0.2125f,
                          -0.0641f * T - 0.8989f, -0.0033f * T + 0.0452f},
                         {-0.0167f * T - 0.2608f, -0.0950f * T + 0.0092f, -0.0079f * T + 0.2102f,
                          -0.0441f * T - 1.6537f, -0.0109f * T + 0.0529f}};
  for (int k = 0; k < 3; ++k) {
    std::copy(c[k], c[k] + 5, coef_[k]);
    norm_[k] = perez(coef_[k], 1.0f, ts);
  }
  if (has_sun()) {
    // Extraterrestrial sun luminance (1.6e9 cd/m^2) through the air mass (Kasten-Young), with
    // more extinction for blue: the low sun turns orange.
    const float elev_deg = std::max(0.0f, 90.0f - ts * 180.0f / kPi);
    const float air_mass = 1.0f / (std::cos(ts) + 0.50572f * std::pow(elev_deg + 6.07995f, -1.6364f));
    const Rgb tau = Rgb(0.65f, 1.0f, 1.6f) * (0.08f * T);
    const Rgb transmittance(std::exp(-tau.x() * air_mass), std::exp(-tau.y() * air_mass), std::exp(-tau.z() * air_mass));
    sun_radiance_ = transmittance * (1.6e6f * kUnitsPerKcd);
  }
  // The ground below the horizon: a diffuse plane lit by the sun and the upper sky.
  if (!p_.compute_ground) return;
  Rgb e_sky = Rgb::Zero();
  const int n = 64;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const float v = 0.5f * (i + 0.5f) / n;  // upper hemisphere only
      const Eigen::Vector3f d = equirect_dir((j + 0.5f) / (2 * n), v);
      e_sky += radiance(d) * (d.z() * (2 * kPi / (2 * n)) * (0.5f * kPi / n) * std::sin(kPi * v));
    }
  const Rgb e_sun = sun_radiance_ * (sun_solid_angle_sr() * std::max(0.0f, sun_.z()));
  ground_ = (e_sky + e_sun) * (p_.ground_albedo / kPi);
}

Rgb Sky::preetham(const Eigen::Vector3f& d) const {
  const float cos_theta = std::max(d.z(), 0.0f);
  const float gamma = std::acos(std::clamp(d.dot(sun_), -1.0f, 1.0f));
  const float Y = zenith_xyY_.z() * perez(coef_[0], cos_theta, gamma) / norm_[0];
  const float x = zenith_xyY_.x() * perez(coef_[1], cos_theta, gamma) / norm_[1];
  const float y = zenith_xyY_.y() * perez(coef_[2], cos_theta, gamma) / norm_[2];
  return xyY_to_linear_srgb(x, y, Y) * kUnitsPerKcd;
}

Rgb Sky::radiance(const Eigen::Vector3f& d) const {
  if (d.z() < 0) return ground_;
  if (p_.overcast) {
    // CIE overcast: L = Lz (1 + 2 cos theta) / 3, slightly blue-grey.
    const float L = p_.overcast_zenith_kcd * kUnitsPerKcd * (1 + 2 * d.z()) / 3;
    return Rgb(0.95f, 1.0f, 1.08f) * L;
  }
  return preetham(d);
}

EnvMap Sky::to_env_map(int width, int height, bool with_ground) const {
  std::vector<Rgb> px(size_t(width) * size_t(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Eigen::Vector3f d = equirect_dir((x + 0.5f) / width, (y + 0.5f) / height);
      px[size_t(y) * size_t(width) + size_t(x)] = (d.z() < 0 && !with_ground) ? Rgb::Zero() : radiance(d);
    }
  return EnvMap(width, height, std::move(px));
}

}  // namespace chatsim::render
