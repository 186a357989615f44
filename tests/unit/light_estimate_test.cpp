// Lighting estimation on analytic panoramas seen through the car's three front cameras: a clear
// sky with the sun in view, the sun behind the car, an overcast sky, and a bright window that
// must not be taken for the sun.
#include <cmath>

#include <gtest/gtest.h>

#include "render/equirect.hpp"
#include "render/light/light_estimate.hpp"
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

// A low sun in a glowing sky: the glow clips the red channel over a wide patch around the sun,
// which is therefore no compact blob; the disc is where two channels clip.
TEST(LightEstimate, ALowSunInAGlowThatClipsOneChannelIsFoundByItsDisc) {
  SkyParams p;
  p.sun_direction = dir_deg(20, 4);
  EnvMap env = panorama(p);
  const float zenith = luminance(env.radiance(Eigen::Vector3f::UnitZ()));
  for (int y = 0; y < env.height(); ++y)
    for (int x = 0; x < env.width(); ++x) {
      const Eigen::Vector3f d = equirect_dir((x + 0.5f) / float(env.width()), (y + 0.5f) / float(env.height()));
      if (d.z() < 0) continue;
      const float apart = std::acos(std::clamp(d.dot(p.sun_direction.normalized()), -1.0f, 1.0f)) * 180 / float(M_PI);
      env.at(x, y) += Rgb(1.0f, 0.3f, 0.08f) * zenith * 8 * std::exp(-apart / 12);
    }
  const auto r = light::evaluate_on_panorama(env, "glow", 1, 240);
  const auto& front = heading(r, 0);
  EXPECT_EQ(front["sun_cue"], "visible") << front.dump();
  EXPECT_LT(front["peak_angular_error_deg"].get<double>(), 3.0) << front.dump();
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

// A grey road under a featureless sky, one car at each of two instants, and the shadow each
// casts for a known sun painted where it falls: the sun comes from the shadows alone (the sky
// says nothing), each car measured in the views of its own instant.
TEST(LightEstimate, ShadowsOfCarsAtTwoInstantsGiveTheSun) {
  const Eigen::Vector3d sun = dir_deg(100, 40).cast<double>();
  const Eigen::Vector3d size(4.5, 1.8, 1.5);
  struct Instant {
    Eigen::Vector3d ego, car;
  };
  const std::vector<Instant> instants{{{0, 0, 1.6}, {9, 3.5, 0.75}}, {{4, 0, 1.6}, {14, -3.5, 0.75}}};
  // Where a ray meets the axis-aligned box (slab test).
  auto hits = [&](const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& c) {
    double t0 = 0, t1 = 1e9;
    for (int k = 0; k < 3; ++k) {
      if (std::abs(d[k]) < 1e-12) {
        if (std::abs(o[k] - c[k]) > size[k] / 2) return false;
        continue;
      }
      double a = (c[k] - size[k] / 2 - o[k]) / d[k], b = (c[k] + size[k] / 2 - o[k]) / d[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    return t0 <= t1;
  };
  std::vector<light::LightView> views;
  std::vector<light::GroundBox> boxes;
  for (size_t i = 0; i < instants.size(); ++i) {
    const auto& in = instants[i];
    light::LightView v;
    v.camera.name = "front";
    v.camera.width = 320, v.camera.height = 200;
    v.camera.fx = v.camera.fy = 200, v.camera.cx = 159.5, v.camera.cy = 99.5;
    Eigen::Matrix3d cv_in_flu;
    cv_in_flu << 0, 0, 1, -1, 0, 0, 0, -1, 0;
    v.camera_to_world = Eigen::Isometry3d::Identity();
    v.camera_to_world.linear() = cv_in_flu;
    v.camera_to_world.translation() = in.ego;
    v.frame = int(i);
    v.rgb = cv::Mat(200, 320, CV_8UC3);
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < 320; ++x) {
        const Eigen::Vector3d d = cv_in_flu * Eigen::Vector3d((x - 159.5) / 200, (y - 99.5) / 200, 1);
        cv::Vec3b c(150, 180, 230);  // sky
        if (hits(in.ego, d.normalized(), in.car)) {
          c = cv::Vec3b(70, 70, 80);  // the car
        } else if (d.z() < 0) {
          const Eigen::Vector3d ground = in.ego + d * (-in.ego.z() / d.z());
          c = hits(ground + Eigen::Vector3d(0, 0, 1e-3), sun, in.car) ? cv::Vec3b(45, 45, 48) : cv::Vec3b(130, 130, 128);
        }
        v.rgb.at<cv::Vec3b>(y, x) = c;
      }
    views.push_back(v);
    boxes.push_back({in.car, size, 0.0, int(i)});
  }
  const auto est = light::estimate_light(views, boxes);
  EXPECT_TRUE(est.sunny);
  EXPECT_EQ(est.sun_cue, "shadows");
  const double err = std::acos(std::clamp(est.sky.sun_direction.normalized().cast<double>().dot(sun), -1.0, 1.0)) * 180 / M_PI;
  EXPECT_LT(err, 10.0) << "estimated " << est.sky.sun_direction.transpose();
}

// The clip's estimate takes the middle frame of equal parts of the clip, and no more frames
// than there are.
TEST(LightEstimate, AClipIsSampledAtTheMiddlesOfEqualParts) {
  scene::Scene s;
  for (int i = 0; i < 40; ++i) {
    scene::Frame f;
    f.index = 100 + i;
    s.frames.push_back(f);
  }
  EXPECT_EQ(light::scene_light_frames(s, 4), (std::vector<int>{105, 115, 125, 135}));
  EXPECT_EQ(light::scene_light_frames(s, 1), (std::vector<int>{120}));
  s.frames.resize(3);
  EXPECT_EQ(light::scene_light_frames(s, 4), (std::vector<int>{100, 101, 102}));
  s.frames.clear();
  EXPECT_TRUE(light::scene_light_frames(s, 4).empty());
}

}  // namespace
}  // namespace chatsim::render
