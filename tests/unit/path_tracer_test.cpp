// The path tracer against answers known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "render/equirect.hpp"
#include "render/path_tracer.hpp"

namespace chatsim::render {
namespace {

scene::Camera test_camera(int w = 32, int h = 32, double fov_deg = 40) {
  scene::Camera c;
  c.name = "test";
  c.width = w;
  c.height = h;
  c.fx = c.fy = (w / 2.0) / std::tan(fov_deg / 2 * M_PI / 180);
  c.cx = (w - 1) / 2.0;
  c.cy = (h - 1) / 2.0;
  return c;
}

// A camera at `eye` looking along `forward` with `up` roughly up (OpenCV: y down).
Eigen::Isometry3d look(const Eigen::Vector3d& eye, const Eigen::Vector3d& forward, const Eigen::Vector3d& up) {
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear().col(0) = x;
  t.linear().col(1) = y;
  t.linear().col(2) = z;
  t.translation() = eye;
  return t;
}

double mean_channel(const cv::Mat& m, int c) { return cv::mean(m)[c]; }

// A furnace test: a unit sphere of `material` under a uniform white sky (64 spp, the sky itself
// not drawn); returns the mean radiance over the pixels it covers and their count.
std::pair<double, int> furnace_sphere(const Material& material) {
  RayScene rs;
  const uint32_t m = rs.add_material(material);
  rs.add_instance(rs.add_prototype(make_sphere(1, 48, 96), {m}), Eigen::Affine3f::Identity());
  rs.commit();
  const EnvMap sky = EnvMap::uniform(Rgb::Constant(1.0f));
  Lighting light;
  light.sky = &sky;
  RenderSettings s;
  s.spp = 64;
  s.include_sky = false;
  const scene::Camera cam = test_camera(16, 16, 10);  // only the sphere in view
  const auto view = render_view(rs, light, cam, look({0, -8, 0}, {0, 1, 0}, {0, 0, 1}), s);
  const cv::Mat covered = view.alpha > 0.999f;
  return {cv::mean(view.radiance, covered)[0], cv::countNonZero(covered)};
}

TEST(EnvMap, PdfIntegratesToOneAndSamplesFollowIt) {
  Sky sky(SkyParams{});
  const EnvMap map = sky.to_env_map(128, 64);
  double integral = 0;
  const int n = 256;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const float v = (i + 0.5f) / n, u = (j + 0.5f) / (2 * n);
      integral += map.pdf(equirect_dir(u, v)) * (2 * M_PI / (2 * n)) * (M_PI / n) * std::sin(M_PI * v);
    }
  EXPECT_NEAR(integral, 1.0, 0.02);
  // Monte Carlo estimate of irradiance from importance sampling matches the numerical integral.
  Rng rng(7);
  Rgb est = Rgb::Zero();
  const int samples = 200000;
  for (int k = 0; k < samples; ++k) {
    float pdf = 0;
    const Eigen::Vector3f d = map.sample(rng.uniform(), rng.uniform(), &pdf);
    if (pdf > 0 && d.z() > 0) est += map.radiance(d) * (d.z() / pdf);
  }
  est /= float(samples);
  const Rgb exact = map.irradiance(Eigen::Vector3f::UnitZ());
  EXPECT_NEAR(est.y() / exact.y(), 1.0, 0.03);
}

TEST(EnvMap, EquirectMappingMatchesTheSceneFormat) {
  EXPECT_NEAR(equirect_uv(Eigen::Vector3f::UnitX()).x(), 0.5f, 1e-6f);   // u = 0.5 faces +x
  EXPECT_NEAR(equirect_uv(Eigen::Vector3f::UnitZ()).y(), 0.0f, 1e-6f);   // v = 0 is +z
  EXPECT_NEAR(equirect_uv(-Eigen::Vector3f::UnitY()).x(), 0.75f, 1e-6f); // to the right of +x
  const Eigen::Vector3f d = Eigen::Vector3f(0.3f, -0.5f, 0.2f).normalized();
  const Eigen::Vector2f uv = equirect_uv(d);
  EXPECT_LT((equirect_dir(uv.x(), uv.y()) - d).norm(), 1e-5f);
}

TEST(PathTracer, DiffusePlaneUnderAUniformSkyReflectsAlbedoTimesSky) {
  RayScene rs;
  const float albedo = 0.6f;
  const uint32_t m = rs.add_material(Material::diffuse("grey", Rgb::Constant(albedo)));
  rs.add_instance(rs.add_prototype(make_quad(-50, -50, 50, 50), {m}), Eigen::Affine3f::Identity());
  rs.commit();
  const EnvMap sky = EnvMap::uniform(Rgb::Constant(2.0f));
  Lighting light;
  light.sky = &sky;
  RenderSettings s;
  s.spp = 64;
  const auto view = render_view(rs, light, test_camera(), look({0, 0, 3}, {0.2, 0, -1}, {1, 0, 0}), s);
  EXPECT_NEAR(mean_channel(view.radiance, 1), albedo * 2.0, 0.01 * albedo * 2.0);
  EXPECT_NEAR(mean_channel(view.alpha, 0), 1.0, 1e-6);
}

TEST(PathTracer, WhiteFurnaceSphereReflectsAlbedoTimesSkyWithEveryBounce) {
  const float albedo = 0.8f;
  const auto [mean, covered] = furnace_sphere(Material::diffuse("white", Rgb::Constant(albedo)));
  EXPECT_GT(covered, 100);
  EXPECT_NEAR(mean, albedo, 0.02);
}

TEST(PathTracer, SunLitPlaneFollowsLambertsCosineLaw) {
  RayScene rs;
  const float albedo = 0.5f;
  const uint32_t m = rs.add_material(Material::diffuse("grey", Rgb::Constant(albedo)));
  rs.add_instance(rs.add_prototype(make_quad(-50, -50, 50, 50), {m}), Eigen::Affine3f::Identity());
  rs.commit();
  Lighting light;
  const float elevation = 30 * kPi / 180;
  light.sun_direction = Eigen::Vector3f(std::cos(elevation), 0, std::sin(elevation));
  light.sun_radiance = Rgb::Constant(1e6f);
  light.sun_cos_max = sun_cos_half_angle();
  RenderSettings s;
  s.spp = 16;
  const auto view = render_view(rs, light, test_camera(), look({0, 0, 3}, {0.1, 0.1, -1}, {1, 0, 0}), s);
  const double expected = albedo / M_PI * 1e6 * sun_solid_angle_sr() * std::sin(elevation);
  EXPECT_NEAR(mean_channel(view.radiance, 0), expected, 0.01 * expected);
}

TEST(PathTracer, MetalFurnaceLosesLittleEnergy) {
  const double v = furnace_sphere(Material::metal("chrome", Rgb::Ones(), 0.3f)).first;
  EXPECT_GT(v, 0.85);  // single-scattering GGX loses a few percent at this roughness
  EXPECT_LT(v, 1.01);
}

// A box standing on a shadow-catcher ground, under a uniform sky of 100 and a bright sun.
struct BoxOnCatcher {
  RayScene rs;
  EnvMap sky = EnvMap::uniform(Rgb::Constant(100.0f));
  Lighting light;
  BoxOnCatcher(const Eigen::Vector3f& size, float centre_height, const Eigen::Vector3f& sun_direction) {
    const uint32_t ground = rs.add_material(Material::shadow_catcher());
    const uint32_t box = rs.add_material(Material::diffuse("box", Rgb::Constant(0.5f)));
    rs.add_instance(rs.add_prototype(make_quad(-50, -50, 50, 50), {ground}), Eigen::Affine3f::Identity(), std::nullopt,
                    {}, mask::kCatcher);
    Eigen::Affine3f at = Eigen::Affine3f::Identity();
    at.translate(Eigen::Vector3f(0, 0, centre_height));
    rs.add_instance(rs.add_prototype(make_box(size), {box}), at, std::nullopt, {}, mask::kForeground);
    rs.commit();
    light.sky = &sky;
    light.sun_direction = sun_direction;
    light.sun_radiance = Rgb::Constant(3e7f);
    light.sun_cos_max = sun_cos_half_angle();
  }
};

TEST(PathTracer, ShadowCatcherRecordsTheShadowOfABoxAndNothingElse) {
  BoxOnCatcher b({2, 2, 2}, 1, Eigen::Vector3f(0, 0, 1));  // sun straight overhead: shadow under the box
  RenderSettings s;
  s.spp = 16;
  s.include_sky = false;
  const scene::Camera cam = test_camera(64, 64, 90);
  const auto c2w = look({0, -6, 8}, {0, 0.6, -1}, {0, 1, 0});
  const auto view = render_view(b.rs, b.light, cam, c2w, s);
  // The ground right beside the box (x = 1.5, in its sun shadow? no: sun overhead) is lit by
  // the sun; a point far away is fully lit; the box itself is covered (alpha 1).
  auto pixel_of = [&](const Eigen::Vector3d& w) {
    const Eigen::Vector3d c = c2w.inverse() * w;
    return cv::Point(int(std::lround(cam.fx * c.x() / c.z() + cam.cx)), int(std::lround(cam.fy * c.y() / c.z() + cam.cy)));
  };
  const cv::Point far = pixel_of({6, 4, 0});
  const cv::Point near = pixel_of({1.3, 0, 0});
  const cv::Point top = pixel_of({0, 0, 2});
  EXPECT_NEAR(view.shadow.at<float>(far), 1.0f, 0.05f);
  EXPECT_LT(view.shadow.at<float>(near), 0.995f);       // some sky hidden by the box
  EXPECT_GT(view.shadow.at<float>(near), 0.85f);        // but the sun still reaches it
  EXPECT_EQ(view.alpha.at<float>(top), 1.0f);
  EXPECT_EQ(view.alpha.at<float>(far), 0.0f);
  EXPECT_EQ(view.radiance.at<cv::Vec3f>(far)[0], 0.0f); // the catcher itself is not drawn
}

// Open ground stops sampling early; everything else is sampled as before, so the image barely
// changes: covered pixels are identical, the shadow differs only where it was nearly 1.
TEST(PathTracer, EarlyStopOnOpenGroundChangesAlmostNothing) {
  BoxOnCatcher b({2, 2, 2}, 1, Eigen::Vector3f(0.5f, 0.3f, 0.8f).normalized());
  RenderSettings s;
  s.spp = 16;
  s.include_sky = false;
  const scene::Camera cam = test_camera(64, 64, 90);
  const auto c2w = look({0, -6, 8}, {0, 0.6, -1}, {0, 1, 0});
  const auto full = render_view(b.rs, b.light, cam, c2w, s);
  s.catcher_early_stop = 4;
  const auto early = render_view(b.rs, b.light, cam, c2w, s);
  cv::Mat covered = full.alpha > 0;
  ASSERT_GT(cv::countNonZero(covered), 50);
  EXPECT_EQ(cv::norm(full.radiance, early.radiance, cv::NORM_INF, covered), 0.0);
  EXPECT_EQ(cv::norm(full.alpha, early.alpha, cv::NORM_INF), 0.0);
  EXPECT_LT(cv::norm(full.shadow, early.shadow, cv::NORM_INF), 0.1);
  EXPECT_LT(cv::norm(full.shadow, early.shadow, cv::NORM_L1) / (64 * 64), 0.003);
  EXPECT_LT(cv::countNonZero(early.shadow < 0.9f), cv::countNonZero(full.shadow < 0.9f) + 3);  // the shadow is kept
  EXPECT_GT(cv::countNonZero(full.shadow < 0.9f), 20);
}

TEST(PathTracer, ShadowCatcherUnderAnOverheadSunIsDarkBelowTheBox) {
  BoxOnCatcher b({2, 2, 0.5f}, 2, Eigen::Vector3f(0, 0, 1));
  RenderSettings s;
  s.spp = 16;
  // Looking up from below the box's edge is awkward; look straight down at the shadow beside
  // a slab raised 2 m: its shadow is a 2 x 2 m square on the ground, seen past the slab.
  const scene::Camera cam = test_camera(64, 64, 60);
  const auto c2w = look({4, 0, 1}, {-1, 0, -0.35}, {0, 0, 1});
  const auto view = render_view(b.rs, b.light, cam, c2w, s);
  const Eigen::Vector3d c = c2w.inverse() * Eigen::Vector3d(0.5, 0, 0);
  const cv::Point under(int(std::lround(cam.fx * c.x() / c.z() + cam.cx)), int(std::lround(cam.fy * c.y() / c.z() + cam.cy)));
  // Sun blocked: what is left is the sky not hidden by the slab, a small share of the light.
  const float sun_e = 3e7f * sun_solid_angle_sr();
  const float sky_e = 100.0f * kPi;
  EXPECT_LT(view.shadow.at<float>(under), sky_e / (sun_e + sky_e) + 0.02f);
}

TEST(PathTracer, MotionBlurSmearsAMovingBox) {
  RayScene rs;
  const uint32_t box = rs.add_material(Material::diffuse("box", Rgb::Constant(0.5f)));
  Eigen::Affine3f a = Eigen::Affine3f::Identity(), b = Eigen::Affine3f::Identity();
  b.translate(Eigen::Vector3f(2, 0, 0));
  rs.add_instance(rs.add_prototype(make_box({1, 1, 1}), {box}), a, b, {}, mask::kForeground);
  rs.commit();
  Lighting light;
  RenderSettings s;
  s.spp = 64;
  s.shutter_open = 0;
  s.shutter_close = 1;
  const scene::Camera cam = test_camera(64, 16, 60);
  const auto view = render_view(rs, light, cam, look({1, -6, 0}, {0, 1, 0}, {0, 0, 1}), s);
  int partial = 0;
  for (int x = 0; x < 64; ++x) {
    const float al = view.alpha.at<float>(8, x);
    if (al > 0.2f && al < 0.8f) ++partial;
  }
  EXPECT_GT(partial, 8);  // a smear, not a sharp-edged box
}

TEST(PathTracer, SameSeedSameImage) {
  RayScene rs;
  const uint32_t m = rs.add_material(Material::coated("paint", Rgb(0.6f, 0.1f, 0.1f), 0.2f));
  rs.add_instance(rs.add_prototype(make_sphere(1, 16, 32), {m}), Eigen::Affine3f::Identity());
  rs.commit();
  Sky sky(SkyParams{});
  const EnvMap map = sky.to_env_map(64, 32);
  const Lighting light = Lighting::from_sky(sky, map);
  RenderSettings s;
  s.spp = 4;
  const auto c2w = look({0, -5, 0}, {0, 1, 0}, {0, 0, 1});
  s.threads = 1;
  const auto a = render_view(rs, light, test_camera(), c2w, s);
  s.threads = 2;
  const auto b = render_view(rs, light, test_camera(), c2w, s);
  EXPECT_EQ(cv::norm(a.radiance, b.radiance, cv::NORM_INF), 0.0);
}

TEST(Sky, PreethamIsBrightestNearTheSunAndItsZenithMatchesTheFormula) {
  SkyParams p;
  p.sun_direction = Eigen::Vector3f(0, std::cos(kPi / 4), std::sin(kPi / 4));
  p.turbidity = 3;
  const Sky sky(p);
  const float near_sun = luminance(sky.radiance(Eigen::Vector3f(0, 0.75f, 0.66f).normalized()));
  const float away = luminance(sky.radiance(Eigen::Vector3f(0, -0.75f, 0.66f).normalized()));
  EXPECT_GT(near_sun, 2 * away);
  // Zenith luminance (Preetham 1999, kcd/m^2) at sun elevation 45 degrees, turbidity 3.
  const double chi = (4.0 / 9.0 - 3.0 / 120.0) * (M_PI - 2 * M_PI / 4);
  const double yz = (4.0453 * 3 - 4.9710) * std::tan(chi) - 0.2155 * 3 + 2.4192;
  EXPECT_NEAR(luminance(sky.radiance(Eigen::Vector3f::UnitZ())) / kUnitsPerKcd, yz, 0.05 * yz);
  // The sun is far brighter than any sky, and dims and reddens toward the horizon.
  EXPECT_GT(luminance(sky.sun_radiance()), 1e4f * near_sun);
  p.sun_direction = Eigen::Vector3f(0, 1, 0.1f);
  const Sky low(p);
  EXPECT_LT(luminance(low.sun_radiance()), luminance(sky.sun_radiance()));
  EXPECT_GT(low.sun_radiance().x() / low.sun_radiance().z(), sky.sun_radiance().x() / sky.sun_radiance().z());
}

TEST(Sky, OvercastHasNoSunAndDependsOnlyOnElevation) {
  SkyParams p;
  p.overcast = true;
  const Sky sky(p);
  EXPECT_FALSE(sky.has_sun());
  const Eigen::Vector3f a = Eigen::Vector3f(1, 0, 1).normalized(), b = Eigen::Vector3f(-1, 0, 1).normalized();
  EXPECT_FLOAT_EQ(luminance(sky.radiance(a)), luminance(sky.radiance(b)));
  EXPECT_NEAR(luminance(sky.radiance(Eigen::Vector3f::UnitZ())) / luminance(sky.radiance(Eigen::Vector3f(1, 0, 0.001f).normalized())),
              3.0f, 0.01f);
}

}  // namespace
}  // namespace chatsim::render
