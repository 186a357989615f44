#pragma once
// sRGB transfer functions and colour helpers. Radiance units follow SCENE_FORMAT.md: an 8-bit
// pixel's linear value (inverse OETF) equals radiance x exposure_s.
#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Core>

namespace chatsim::render {

using Rgb = Eigen::Vector3f;

inline float srgb_oetf(float linear) {
  const float x = std::clamp(linear, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}
inline float srgb_inverse_oetf(float encoded) {
  const float x = std::clamp(encoded, 0.0f, 1.0f);
  return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}
// 8-bit code values to linear, by table (256 entries).
inline const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> t = [] {
    std::array<float, 256> a{};
    for (int i = 0; i < 256; ++i) a[size_t(i)] = srgb_inverse_oetf(float(i) / 255.0f);
    return a;
  }();
  return t;
}

inline float luminance(const Rgb& c) { return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z(); }

// An 8-bit sRGB colour (as in objects.json's color_rgb) as linear reflectance.
inline Rgb linear_from_srgb8(int r, int g, int b) {
  const auto& t = srgb_to_linear_table();
  return {t[size_t(std::clamp(r, 0, 255))], t[size_t(std::clamp(g, 0, 255))], t[size_t(std::clamp(b, 0, 255))]};
}

}  // namespace chatsim::render
