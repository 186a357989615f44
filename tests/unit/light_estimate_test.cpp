// Lighting estimation on analytic panoramas seen through the car's three front cameras (a clear
// sky with the sun in view, the sun behind the car, an overcast sky, a bright window that must
// not be taken for the sun; the evaluation's check for a panorama whose own sun is clipped and
// its probe of the sky alone)
// and on painted streets (cars' shadows, a pale strip in the sky mask, shadowless cars, the sky
// mask, black, white and skyless frames).
#include <cmath>
#include <functional>
#include <optional>
#include <tuple>

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
  EXPECT_TRUE(front["sun_in_view"].get<bool>());
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

// Behind the cameras only the sky's gradient tells where the sun is, and on a Preetham sky it
// trades the sun's direction against turbidity: this sky (turbidity 3) is 64 degrees off with
// the estimator's turbidities (2.5, 4, 6), within 1.2 degrees at 2.5 or 4 (2026-12-05). What we
// can promise is no false "visible" sun and the right hemisphere; the benchmark reports such cases.
TEST(LightEstimate, SunBehindTheCarIsNotSeenAndLandsInTheRightHemisphere) {
  SkyParams p;
  p.sun_direction = dir_deg(180, 30);
  const auto r = light::evaluate_on_panorama(panorama(p), "behind", 1, 240);
  const auto& front = heading(r, 0);
  EXPECT_EQ(front["sky_type"], "sunny");
  EXPECT_FALSE(front["sun_in_view"].get<bool>());
  EXPECT_NE(front["sun_cue"], "visible");
  EXPECT_LT(front["peak_angular_error_deg"].get<double>(), 90.0);
}

// The evaluation's probe of the sky alone: on a sky the model describes exactly (its turbidity
// among the probe's), the true sun fits almost perfectly, and the grid's best direction is the
// sun's, in view and behind the car. (The "true" sun is the panorama's brightest pixel, 0.7 deg
// wide, so the grid may fit a hair better.)
TEST(LightEval, TheSkyAloneFitsAnAnalyticSkyBestAtItsOwnSun) {
  for (const auto& [az, el, seen] : {std::tuple{10.0, 10.0, true}, std::tuple{180.0, 30.0, false}}) {
    SkyParams p;
    p.sun_direction = dir_deg(az, el);
    const auto r = light::evaluate_on_panorama(panorama(p), "analytic", 1, 240);
    const auto& sky = heading(r, 0)["sky_alone"];
    ASSERT_FALSE(sky["rms_log_error_at_true_sun"].is_null()) << sky.dump();
    const double at = sky["rms_log_error_at_true_sun"], best = sky["rms_log_error_at_best"];
    EXPECT_LT(at, 0.03) << sky.dump();
    EXPECT_LT(at, best + 0.005) << sky.dump();
    EXPECT_LT(sky["best_angular_error_deg"].get<double>(), 3.0) << (seen ? "in view " : "behind ") << sky.dump();
  }
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

// A pale wall facing the sun, lit by the whole panorama (sun included), below the horizon
// behind the car; then the same panorama with its sun clipped to the sky around it, as an HDRI
// merged from too few exposures keeps it. Only the clipped one is flagged.
TEST(LightEval, APanoramaWhoseSunIsClippedIsFlaggedByItsOverbrightWall) {
  SkyParams p;
  p.sun_direction = dir_deg(180, 20);
  EnvMap env = panorama(p);
  const float wall = 0.8f / float(M_PI) * luminance(env.irradiance(dir_deg(180, 0)));
  for (int y = 0; y < env.height(); ++y)
    for (int x = 0; x < env.width(); ++x) {
      const Eigen::Vector3f d = equirect_dir((x + 0.5f) / float(env.width()), (y + 0.5f) / float(env.height()));
      const double az = std::atan2(d.y(), d.x()) * 180 / M_PI, el = std::asin(d.z()) * 180 / M_PI;
      if (std::abs(az) > 150 && el > -20 && el < -2) env.at(x, y) = Rgb(1, 1, 1) * wall;
    }
  EXPECT_LT(light::overbright_ground_share(env), light::kClippedSunGroundShare);
  const Eigen::Vector2f uv = equirect_uv(p.sun_direction.normalized());
  const int sx = int(uv.x() * float(env.width())), sy = int(uv.y() * float(env.height()));
  env.at(sx, sy) = env.at(sx + 2, sy);
  EXPECT_GT(light::overbright_ground_share(env), light::kClippedSunGroundShare);
  const auto r = light::evaluate_on_panorama(env, "clipped", 1, 240);
  EXPECT_TRUE(r["peak_clipped"].get<bool>()) << r.dump();
}

// A 320x200 front camera at `ego` looking along +x (world z up), each pixel coloured by its ray.
light::LightView front_view(const Eigen::Vector3d& ego, int frame, const std::function<cv::Vec3b(const Eigen::Vector3d&)>& colour) {
  light::LightView v;
  v.camera.name = "front";
  v.camera.width = 320, v.camera.height = 200;
  v.camera.fx = v.camera.fy = 200, v.camera.cx = 159.5, v.camera.cy = 99.5;
  Eigen::Matrix3d cv_in_flu;
  cv_in_flu << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  v.camera_to_world = Eigen::Isometry3d::Identity();
  v.camera_to_world.linear() = cv_in_flu;
  v.camera_to_world.translation() = ego;
  v.frame = frame;
  v.rgb = cv::Mat(200, 320, CV_8UC3);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 320; ++x) v.rgb.at<cv::Vec3b>(y, x) = colour((cv_in_flu * Eigen::Vector3d((x - 159.5) / 200, (y - 99.5) / 200, 1)).normalized());
  return v;
}

// Whether a ray meets an axis-aligned box (slab test).
bool hits_box(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Eigen::Vector3d& c, const Eigen::Vector3d& size) {
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
}

const Eigen::Vector3d kCarSize(4.5, 1.8, 1.5);

// Views of one car per instant on a grey road; the road darkened where the car's shadow falls
// for `sun` (none: no shadow), the sky as `sky` colours it.
struct Street {
  std::vector<light::LightView> views;
  std::vector<light::GroundBox> boxes;
};
Street street(const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& ego_and_car, const std::optional<Eigen::Vector3d>& sun,
              const std::function<cv::Vec3b(const Eigen::Vector3d&)>& sky, const cv::Vec3b& road) {
  Street out;
  for (size_t i = 0; i < ego_and_car.size(); ++i) {
    const auto& [ego, car] = ego_and_car[i];
    out.views.push_back(front_view(ego, int(i), [&](const Eigen::Vector3d& d) {
      if (hits_box(ego, d, car, kCarSize)) return cv::Vec3b(70, 70, 80);
      if (d.z() >= 0) return sky(d);
      const Eigen::Vector3d ground = ego + d * (-ego.z() / d.z());
      return sun && hits_box(ground + Eigen::Vector3d(0, 0, 1e-3), *sun, car, kCarSize) ? cv::Vec3b(45, 45, 48) : road;
    }));
    out.boxes.push_back({car, kCarSize, 0.0, int(i)});
  }
  return out;
}

// A grey road under a featureless sky, one car at each of two instants, and the shadow each
// casts for a known sun painted where it falls: the sun comes from the shadows alone (the sky
// says nothing), each car measured in the views of its own instant.
TEST(LightEstimate, ShadowsOfCarsAtTwoInstantsGiveTheSun) {
  const Eigen::Vector3d sun = dir_deg(100, 40).cast<double>();
  const auto s = street({{{0, 0, 1.6}, {9, 3.5, 0.75}}, {{4, 0, 1.6}, {14, -3.5, 0.75}}}, sun,
                        [](const Eigen::Vector3d&) { return cv::Vec3b(150, 180, 230); }, cv::Vec3b(130, 130, 128));
  const auto est = light::estimate_light(s.views, s.boxes);
  EXPECT_TRUE(est.sunny);
  EXPECT_EQ(est.sun_cue, "shadows");
  const double err = std::acos(std::clamp(est.sky.sun_direction.normalized().cast<double>().dot(sun), -1.0, 1.0)) * 180 / M_PI;
  EXPECT_LT(err, 10.0) << "estimated " << est.sky.sun_direction.transpose();
}

// The same street, and a pale facade strip, smooth and ending above the roofs, taken into the
// sky mask with the sky (as parts of facades cut off by windows are on the demo street): the
// shadows decide the sun, and the sky's level comes from the sky, not pulled up by the strip
// (three times brighter, a third of the mask: a least-squares scale was 1.35 times too bright).
TEST(LightEstimate, APaleStripInTheSkyMaskDoesNotRaiseTheSkysScale) {
  const Eigen::Vector3d sun = dir_deg(100, 40).cast<double>();
  const cv::Vec3b blue(100, 125, 170);
  const auto s = street({{{0, 0, 1.6}, {9, 3.5, 0.75}}, {{4, 0, 1.6}, {14, -3.5, 0.75}}}, sun,
                        [&](const Eigen::Vector3d& d) {
                          const double left = d.y() / d.x();
                          if (d.z() < 0.05) return cv::Vec3b(60, 60, 60);  // roofs
                          return left > 0.1 && left < 0.7 && d.z() > 0.09 ? cv::Vec3b(205, 205, 210) : blue;
                        },
                        cv::Vec3b(130, 130, 128));
  const auto est = light::estimate_light(s.views, s.boxes);
  ASSERT_EQ(est.sun_cue, "shadows");
  const EnvMap dome = est.dome(256, 128);
  const auto& lin = srgb_to_linear_table();
  const float blue_lum = luminance(Rgb(lin[blue[0]], lin[blue[1]], lin[blue[2]]));
  std::vector<double> ratios;  // the dome against the blue sky, where it is in view
  for (double az = -30; az <= 0; az += 3)
    for (double el = 5; el <= 20; el += 3) ratios.push_back(std::log10(luminance(dome.radiance(dir_deg(az, el))) / blue_lum));
  std::nth_element(ratios.begin(), ratios.begin() + long(ratios.size() / 2), ratios.end());
  EXPECT_LT(std::abs(ratios[ratios.size() / 2]), 0.06) << ratios[ratios.size() / 2] << " " << est.to_json("").dump();
}

// Overcast, as on the demo street: a sky clipped white but for a pale band above the roofs
// (its only measured pixels, brighter to one side, which a clear sky with its sun there fits
// better than an overcast one) and cars at three instants that cast no shadow. Before version
// 4 this was called sunny from the band.
TEST(LightEstimate, ShadowlessCarsUnderAClippedSkyAreOvercast) {
  const auto s = street({{{0, 0, 1.6}, {9, 3.5, 0.75}}, {{4, 0, 1.6}, {14, -3.5, 0.75}}, {{8, 0, 1.6}, {16, 3.0, 0.75}}}, std::nullopt,
                        [](const Eigen::Vector3d& d) {
                          // White from 11.5 deg up; below, a band brighter to the left.
                          const double t = std::clamp((d.z() - 0.02) / 0.18, 0.0, 1.0), left = std::clamp(d.y() + 0.5, 0.0, 1.0);
                          const double r = 120 + 80 * left, g = 150 + 60 * left, b = 215 + 30 * left;
                          return cv::Vec3b(uchar(r + (255 - r) * t), uchar(g + (255 - g) * t), uchar(b + (255 - b) * t));
                        },
                        cv::Vec3b(100, 100, 100));
  const auto est = light::estimate_light(s.views, s.boxes);
  EXPECT_FALSE(est.sunny) << est.to_json("").dump();
}

// Degenerate input (a lens cap, a blown-out frame, a garage with no sky, no views at all) gives
// a finite overcast estimate, not NaNs or a crash: there is no sun to find.
TEST(LightEstimate, DegenerateImagesGiveAFiniteOvercastSky) {
  const std::vector<std::pair<std::string, std::function<cv::Vec3b(const Eigen::Vector3d&)>>> cases = {
      {"black", [](const Eigen::Vector3d&) { return cv::Vec3b(0, 0, 0); }},
      {"white", [](const Eigen::Vector3d&) { return cv::Vec3b(255, 255, 255); }},
      {"no sky", [](const Eigen::Vector3d& d) { return d.z() > 0 ? cv::Vec3b(60, 55, 50) : cv::Vec3b(90, 90, 90); }},
  };
  for (const auto& [name, colour] : cases) {
    const auto s = street({{{0, 0, 1.6}, {9, 3.5, 0.75}}}, std::nullopt, colour, colour(Eigen::Vector3d(1, 0, -1).normalized()));
    for (const auto& boxes : {s.boxes, std::vector<light::GroundBox>{}}) {
      const auto est = light::estimate_light(s.views, boxes);
      SCOPED_TRACE(name + (boxes.empty() ? ", no boxes" : ", one car"));
      EXPECT_FALSE(est.sunny) << est.to_json("").dump();
      EXPECT_TRUE(std::isfinite(est.scale)) << est.to_json("").dump();
      EXPECT_TRUE(est.sun_radiance.allFinite());
      // No unclipped sky measured: no fit error to report (it was printed as 1e15).
      EXPECT_TRUE(est.to_json("")["fit_rms_log_error"].is_null()) << est.to_json("").dump();
      const EnvMap dome = est.dome(32, 16);
      for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_TRUE(dome.at(x, y).allFinite()) << x << "," << y;
    }
  }
  const auto none = light::estimate_light({}, {});
  EXPECT_FALSE(none.sunny);
  EXPECT_TRUE(std::isfinite(none.scale));
}

// A smooth pale wall reaching from the top of the image to below the horizon is not sky (it
// goes on below it); the sky beside it, above dark roofs, is; a sunlit treetop in it is not.
TEST(SkyMask, APaleWallGoingOnBelowTheHorizonIsNotSky) {
  const auto v = front_view({0, 0, 1.6}, 0, [](const Eigen::Vector3d& d) {
    if (d.y() < -0.1) return cv::Vec3b(200, 200, 205);                                    // the wall, on the right
    if (d.z() > 0.35 && std::abs(d.y() - 0.15) < 0.06) return cv::Vec3b(120, 220, 110);  // a treetop
    if (d.z() > 0.15) return cv::Vec3b(150, 180, 230);                                     // sky
    return d.z() > 0 ? cv::Vec3b(60, 60, 60) : cv::Vec3b(110, 110, 110);                  // roofs, road
  });
  const cv::Mat mask = light::sky_mask(v);
  auto at = [&](const Eigen::Vector3d& world) {
    const Eigen::Vector3d c = v.camera_to_world.linear().transpose() * world;
    return mask.at<uchar>(int(std::lround(c.y() / c.z() * 200 + 99.5)), int(std::lround(c.x() / c.z() * 200 + 159.5)));
  };
  EXPECT_EQ(at({1, 0.3, 0.4}), 255) << "the sky";
  EXPECT_EQ(at({1, -0.3, 0.4}), 0) << "the wall";
  EXPECT_EQ(at({1, 0.15, 0.45}), 0) << "the treetop";
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
