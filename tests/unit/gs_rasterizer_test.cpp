// The Gaussian rasteriser's gradients against finite differences (and Gaussians left out of
// the pose's), and its images against what a Gaussian must look like.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "render/gs/rasterizer.hpp"

namespace chatsim::render::gs {
namespace {

GsView small_view() {
  GsView v;
  v.width = 40, v.height = 30;
  v.fx = v.fy = 40;
  v.cx = 19.5f, v.cy = 14.5f;
  return v;  // at the origin looking along +z (OpenCV axes = world axes)
}

Gaussians random_gaussians(int n, uint64_t seed) {
  std::mt19937 rng{uint32_t(seed)};
  std::uniform_real_distribution<float> u(-1, 1);
  Gaussians g;
  for (int i = 0; i < n; ++i) {
    g.add({0.5f * u(rng), 0.4f * u(rng), 3 + 0.8f * u(rng)}, 0.12f + 0.05f * u(rng), {0.3f * u(rng), 0.3f * u(rng), 0.3f * u(rng)},
          0.5f + 0.3f * u(rng));
    float* p = g.at(size_t(i));
    p[kScaleX] += 0.3f * u(rng), p[kScaleY] += 0.3f * u(rng);
    p[kRotW] = 1 + 0.2f * u(rng), p[kRotX] = 0.3f * u(rng), p[kRotY] = 0.3f * u(rng), p[kRotZ] = 0.3f * u(rng);
    for (int c = 0; c < 3; ++c) p[kColor + 4 * c + 1] = 0.2f * u(rng), p[kColor + 4 * c + 3] = 0.2f * u(rng);
  }
  return g;
}

struct Weights {
  cv::Mat rad, depth, alpha;
};

Weights random_weights(const GsView& v, uint64_t seed) {
  Weights w{cv::Mat(v.height, v.width, CV_32FC3), cv::Mat(v.height, v.width, CV_32FC1), cv::Mat(v.height, v.width, CV_32FC1)};
  cv::RNG rng(seed);
  rng.fill(w.rad, cv::RNG::UNIFORM, -1, 1);
  rng.fill(w.depth, cv::RNG::UNIFORM, -0.3, 0.3);
  rng.fill(w.alpha, cv::RNG::UNIFORM, -1, 1);
  return w;
}

double loss(Rasterizer& r, const Gaussians& g, const SkyTexture* sky, const GsView& v, const Weights& w) {
  const GsImage img = r.forward(g, sky, v);
  return w.rad.dot(img.radiance) + w.depth.dot(img.depth) + w.alpha.dot(img.alpha);
}

TEST(GsRasterizer, GradientsMatchFiniteDifferences) {
  const GsView v = small_view();
  Gaussians g = random_gaussians(12, 3);
  SkyTexture sky(16, 8, 0.1f);
  const Weights w = random_weights(v, 5);
  Rasterizer r;
  r.min_alpha = 1e-9f;  // no cut-offs: finite differences must not jump over them
  r.extent_sigma = 7;
  r.forward(g, &sky, v);
  GsGrads grads;
  grads.reset(g.size(), size_t(sky.width() * sky.height()));
  r.backward(g, &sky, w.rad, w.depth, w.alpha, grads);
  int checked = 0, bad = 0;
  for (size_t i = 0; i < g.size(); ++i)
    for (int k = 0; k < kParamCount; ++k) {
      const float h = 4e-3f;
      const float keep = g.at(i)[k];
      g.at(i)[k] = keep + h;
      const double lp = loss(r, g, &sky, v, w);
      g.at(i)[k] = keep - h;
      const double lm = loss(r, g, &sky, v, w);
      g.at(i)[k] = keep;
      const double fd = (lp - lm) / (2 * h), an = grads.gaussians[i * kParamCount + size_t(k)];
      if (std::abs(fd) < 1e-3 && std::abs(an) < 1e-3) continue;
      ++checked;
      // Float images limit finite differences to about 1e-3.
      if (std::abs(fd - an) > 0.05 * std::max(std::abs(fd), std::abs(an)) + 3e-3) {
        ++bad;
        ADD_FAILURE() << "gaussian " << i << " param " << k << ": analytic " << an << " vs numeric " << fd;
        if (bad > 10) return;
      }
    }
  EXPECT_GT(checked, 100);
  // The sky texels behind the Gaussians.
  for (size_t t = 0; t < sky.data().size(); t += 7) {
    const float keep = sky.data()[t];
    sky.data()[t] = keep + 1e-3f;
    const double lp = loss(r, g, &sky, v, w);
    sky.data()[t] = keep - 1e-3f;
    const double lm = loss(r, g, &sky, v, w);
    sky.data()[t] = keep;
    const double fd = (lp - lm) / 2e-3;
    EXPECT_NEAR(grads.sky[t], fd, 0.03 * std::abs(fd) + 2e-3) << "sky texel " << t;
  }
}

// Training is reproducible only if the backward pass sums the same terms in the same order on
// every run: per-thread partial sums must cover the same tiles each time.
TEST(GsRasterizer, GradientsAreBitForBitTheSameOnEveryRunWithSeveralThreads) {
  GsView v = small_view();
  v.width = 160, v.height = 120, v.fx = v.fy = 120, v.cx = 79.5f, v.cy = 59.5f;  // 80 tiles
  const Gaussians g = random_gaussians(400, 11);
  SkyTexture sky(16, 8, 0.1f);
  const Weights w = random_weights(v, 13);
  Rasterizer r;
  r.threads = 4;
  auto run = [&] {
    r.forward(g, &sky, v);
    GsGrads grads;
    grads.reset(g.size(), size_t(sky.width() * sky.height()));
    r.backward(g, &sky, w.rad, w.depth, w.alpha, grads);
    return grads;
  };
  const GsGrads first = run();
  for (int k = 0; k < 8; ++k) {
    const GsGrads again = run();
    ASSERT_EQ(again.gaussians, first.gaussians) << "run " << k;
    ASSERT_EQ(again.sky, first.sky) << "run " << k;
    ASSERT_EQ(again.pose, first.pose) << "run " << k;
  }
  // The rasteriser keeps its buffers between calls: one run on a larger model without a sky
  // in between changes nothing either.
  const Gaussians other = random_gaussians(600, 17);
  r.forward(other, nullptr, v);
  GsGrads other_grads;
  other_grads.reset(other.size(), 0);
  r.backward(other, nullptr, w.rad, w.depth, w.alpha, other_grads);
  const GsGrads after_other = run();
  EXPECT_EQ(after_other.gaussians, first.gaussians);
  EXPECT_EQ(after_other.sky, first.sky);
  EXPECT_EQ(after_other.pose, first.pose);
}

TEST(GsRasterizer, PoseGradientMatchesMovingTheCamera) {
  GsView v = small_view();
  const Gaussians g = random_gaussians(20, 7);
  Weights w = random_weights(v, 9);
  Rasterizer r;
  r.min_alpha = 1e-9f;
  r.extent_sigma = 7;
  r.forward(g, nullptr, v);
  GsGrads grads;
  grads.reset(g.size(), 0);
  r.backward(g, nullptr, w.rad, w.depth, w.alpha, grads);
  for (int k = 3; k < 6; ++k) {  // translations (camera frame)
    Eigen::Vector3f e = Eigen::Vector3f::Zero();
    e[k - 3] = 1e-3f;
    GsView a = v, b = v;
    a.center = v.center + v.rotation * e;
    b.center = v.center - v.rotation * e;
    const double fd = (loss(r, g, nullptr, a, w) - loss(r, g, nullptr, b, w)) / 2e-3;
    EXPECT_NEAR(grads.pose[k], fd, 0.05 * std::abs(fd) + 0.02) << "translation " << k - 3;
  }
  for (int k = 0; k < 3; ++k) {  // rotations
    Eigen::Vector3f e = Eigen::Vector3f::Zero();
    e[k] = 1e-3f;
    GsView a = v, b = v;
    a.rotation = v.rotation * Eigen::AngleAxisf(1e-3f, e.normalized()).toRotationMatrix();
    b.rotation = v.rotation * Eigen::AngleAxisf(-1e-3f, e.normalized()).toRotationMatrix();
    const double fd = (loss(r, g, nullptr, a, w) - loss(r, g, nullptr, b, w)) / 2e-3;
    EXPECT_NEAR(grads.pose[k], fd, 0.05 * std::abs(fd) + 0.05) << "rotation " << k;
  }
}

TEST(GsRasterizer, GaussiansLeftOutOfThePoseGradientChangeNothingElse) {
  const GsView v = small_view();
  const Gaussians g = random_gaussians(20, 7);
  const Weights w = random_weights(v, 9);
  Rasterizer r;
  auto grads_with = [&](const std::vector<uint8_t>* blind) {
    r.pose_blind = blind;
    r.forward(g, nullptr, v);
    GsGrads out;
    out.reset(g.size(), 0);
    r.backward(g, nullptr, w.rad, w.depth, w.alpha, out);
    return out;
  };
  std::vector<uint8_t> even(g.size()), odd(g.size()), all(g.size(), 1);
  for (size_t i = 0; i < g.size(); ++i) (i % 2 ? odd : even)[i] = 1;
  const GsGrads none_blind = grads_with(nullptr), even_blind = grads_with(&even), odd_blind = grads_with(&odd), all_blind = grads_with(&all);
  EXPECT_EQ(even_blind.gaussians, none_blind.gaussians);
  EXPECT_EQ(all_blind.screen, none_blind.screen);
  EXPECT_EQ(all_blind.pose.norm(), 0.0f);
  // Each Gaussian's share of the pose gradient: the two halves add up to the whole, and each
  // half is a real part of it.
  EXPECT_LT((even_blind.pose + odd_blind.pose - none_blind.pose).norm(), 1e-4f * none_blind.pose.norm());
  EXPECT_GT((even_blind.pose - none_blind.pose).norm(), 0.1f * none_blind.pose.norm());
  EXPECT_GT((odd_blind.pose - none_blind.pose).norm(), 0.1f * none_blind.pose.norm());
}

TEST(GsRasterizer, OneOpaqueGaussianLooksLikeAGaussianInFrontOfTheSky) {
  GsView v = small_view();
  Gaussians g;
  g.add({0, 0, 4}, 0.2f, {std::log(2.0f), std::log(2.0f), std::log(2.0f)}, 0.9f);
  SkyTexture sky(8, 4, std::log(0.5f));
  Rasterizer r;
  const GsImage img = r.forward(g, &sky, v);
  // Centre pixel (19.5, 14.5 lies between pixels; take the nearest): 0.9 of the way to 2.
  const float c = img.radiance.at<cv::Vec3f>(14, 19)[0];
  EXPECT_NEAR(c, 0.9f * 2 * std::exp(-0.5f * (0.25f + 0.25f) / (0.04f * 100 + 0.3f)) + 0.5f * (1 - 0.9f * std::exp(-0.5f * 0.5f / 4.3f)), 0.02);
  EXPECT_NEAR(img.radiance.at<cv::Vec3f>(0, 0)[1], 0.5f, 1e-4f);  // far corner: sky only
  EXPECT_NEAR(img.depth.at<float>(14, 19) / img.alpha.at<float>(14, 19), 4.0f, 1e-3f);
}

TEST(GsRasterizer, AThinTiltedGaussianCoversExactlyItsCutEllipseAcrossTiles) {
  // Footprints much longer than wide, tilted and crossing tile borders: the pixel loops walk
  // each row's span of the ellipse only, so a span cut short would leave pixels empty (at 8 deg
  // a row's span is over 8 pixels long: halving it fails this test).
  for (const float degrees : {8.0f, 30.0f}) {
    SCOPED_TRACE(degrees);
    GsView v;
    v.width = 64, v.height = 48;
    v.fx = v.fy = 40;
    v.cx = 31.3f, v.cy = 15.8f;
    const float theta = degrees * std::numbers::pi_v<float> / 180, z = 4, opacity = 0.9f;
    Gaussians g;
    g.add({0, 0, z}, 0.5f, {0, 0, 0}, opacity);
    float* p = g.at(0);
    p[kScaleY] = std::log(0.02f), p[kScaleZ] = std::log(0.02f);
    p[kRotW] = std::cos(theta / 2), p[kRotX] = 0, p[kRotY] = 0, p[kRotZ] = std::sin(theta / 2);
    Rasterizer r;
    const GsImage img = r.forward(g, nullptr, v);
    // On the optical axis the footprint is (f / z)^2 R diag(0.5^2, 0.02^2) R^T plus 0.3 px^2.
    const Eigen::Matrix2f R = Eigen::Rotation2Df(theta).toRotationMatrix();
    const float k = v.fx / z;
    const Eigen::Matrix2f S = k * k * R * Eigen::Vector2f(0.25f, 0.0004f).asDiagonal() * R.transpose() + 0.3f * Eigen::Matrix2f::Identity();
    const Eigen::Matrix2f conic = S.inverse();
    int inside = 0, covered = 0;
    float worst = 0;
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x) {
        const Eigen::Vector2f d(float(x) - v.cx, float(y) - v.cy);
        const float q = d.dot(conic * d);
        if (std::abs(q - 9) < 0.05f) continue;  // on the cut itself rounding may go either way
        // Cut at 3 deviations (extent_sigma): this opacity stays above min_alpha further out.
        const float want = q <= 9 ? opacity * std::exp(-0.5f * q) : 0.0f;
        const float got = img.alpha.at<float>(y, x);
        inside += want > 0, covered += got > 0;
        worst = std::max(worst, std::abs(got - want));
      }
    EXPECT_GT(inside, 60);  // about 30 px long: it reaches into four tiles
    EXPECT_EQ(covered, inside);
    EXPECT_LT(worst, 1e-5f);
  }
}

}  // namespace
}  // namespace chatsim::render::gs
