// Lighting estimation on analytic panoramas seen through the car's three front cameras: a clear
// sky with the sun in view, the sun behind the car, an overcast sky, and a bright window that
// must not be taken for the sun.
#include <cmath>

#include <gtest/gtest.h>

#include "render/equirect.hpp"
#include "render/light/light_eval.hpp"
#include "render/sky.hpp"

namespace chatsim::render {
namespace {

Eigen::Vector3f dir_deg(double az, double el) {
  const double a = az * M_PI / 180, e = el * M_PI / 180;
  return Eigen::Vector3f(float(std::cos(e) * std::cos(a)), float(std::cos(e) * std::sin(a)), float(std::sin(e)));
}

// The sky as an equirect map with the sun disc's power in the pixel around its direction.
EnvMap panorama(const SkyParams& p, int w = 512, int h = 256) {
  const Sky sky(p);
  EnvMap env = sky.to_env_map(w, h, true);
  if (sky.has_sun()) {
    const Eigen::Vector3f s = sky.sun_direction();
    const Eigen::Vector2f uv = equirect_uv(s);
    const int x = std::clamp(int(uv.x() * float(w)), 0, w - 1), y = std::clamp(int(uv.y() * float(h)), 0, h - 1);
    const double pixel_sr = (2 * M_PI / w) * (M_PI / h) * std::sqrt(std::max(0.0f, 1 - s.z() * s.z()));
    env.at(x, y) += sky.sun_radiance() * float(sun_solid_angle_sr() / pixel_sr);
  }
  return env;
}

const nlohmann::json& heading(const nlohmann::json& r, double deg) {
  for (const auto& h : r["headings"])
    if (std::abs(h["heading_deg"].get<double>() - deg) < 1e-6) return h;
  throw std::runtime_error("no heading");
}

TEST(LightEstimate, ClearSkyWithTheSunInViewIsFoundWithinAFewDegrees) {
  SkyParams p;
  p.sun_direction = dir_deg(10, 10);
  const auto r = light::evaluate_on_panorama(panorama(p), "clear", 1, 240);
  const auto& front = heading(r, 0);
  EXPECT_EQ(front["sky_type"], "sunny");
  EXPECT_EQ(front["sun_cue"], "visible");
  EXPECT_LT(front["peak_angular_error_deg"].get<double>(), 3.0);
  EXPECT_LT(front["log10_intensity_error"].get<double>(), 0.5);
}

// The sky gradient alone says little about a sun behind the cameras (Preetham is flat away
// from the sun): what we can promise is no false "visible" sun and the right hemisphere. The
// measured error here is about 64 degrees; the benchmark reports such cases.
TEST(LightEstimate, SunBehindTheCarIsNotSeenAndLandsInTheRightHemisphere) {
  SkyParams p;
  p.sun_direction = dir_deg(180, 30);
  const auto r = light::evaluate_on_panorama(panorama(p), "behind", 1, 240);
  const auto& front = heading(r, 0);
  EXPECT_EQ(front["sky_type"], "sunny");
  EXPECT_NE(front["sun_cue"], "visible");
  EXPECT_LT(front["peak_angular_error_deg"].get<double>(), 90.0);
}

TEST(LightEstimate, OvercastSkyIsReportedAsOvercast) {
  SkyParams p;
  p.overcast = true;
  const auto r = light::evaluate_on_panorama(panorama(p), "overcast", 2, 240);
  for (const auto& h : r["headings"]) EXPECT_EQ(h["sky_type"], "overcast") << h.dump();
}

TEST(LightEstimate, ABrightWindowInAFacadeIsNotTheSun) {
  SkyParams p;
  p.sun_direction = dir_deg(180, 40);
  EnvMap env = panorama(p);
  // A grey facade ahead up to 15 degrees, with a small window reflecting far above white.
  for (int y = 0; y < env.height(); ++y)
    for (int x = 0; x < env.width(); ++x) {
      const Eigen::Vector3f d = equirect_dir((x + 0.5f) / float(env.width()), (y + 0.5f) / float(env.height()));
      const double az = std::atan2(d.y(), d.x()) * 180 / M_PI, el = std::asin(d.z()) * 180 / M_PI;
      if (std::abs(az) < 30 && el > -2 && el < 15) env.at(x, y) = Rgb(0.3f, 0.3f, 0.3f) * luminance(env.radiance(Eigen::Vector3f::UnitZ()));
      if (std::abs(az - 5) < 1.5 && std::abs(el - 6) < 1.5) env.at(x, y) = Rgb(1, 1, 1) * 1e3f * luminance(env.radiance(Eigen::Vector3f::UnitZ()));
    }
  const auto r = light::evaluate_on_panorama(env, "window", 1, 240);
  EXPECT_NE(heading(r, 0)["sun_cue"], "visible");
}

}  // namespace
}  // namespace chatsim::render
