// The SSIM loss's value is the metric's, and its gradient is the value's (finite differences).
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "render/gs/ssim_loss.hpp"
#include "render/image_metrics.hpp"

namespace chatsim::render::gs {
namespace {

cv::Mat random_image(int w, int h, uint32_t seed) {
  cv::Mat m(h, w, CV_32FC3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.1f, 0.9f);
  for (auto it = m.begin<cv::Vec3f>(); it != m.end<cv::Vec3f>(); ++it) *it = {u(rng), u(rng), u(rng)};
  cv::GaussianBlur(m, m, cv::Size(5, 5), 1.0);  // some structure, not only noise
  return m;
}

TEST(GsSsimLoss, ValueIsTheMetric) {
  const cv::Mat a = random_image(40, 30, 1), b = random_image(40, 30, 2);
  cv::Mat grad, a8, b8;
  SsimLoss loss;
  const double s = loss.value_and_gradient(a, b, grad);
  a.convertTo(a8, CV_8UC3, 255), b.convertTo(b8, CV_8UC3, 255);
  EXPECT_NEAR(s, ssim(a8, b8), 0.01);  // the metric reads 8-bit images
  cv::Mat same;
  EXPECT_NEAR(loss.value_and_gradient(a, a, same), 1.0, 1e-9);
  EXPECT_LT(cv::norm(same, cv::NORM_INF), 1e-6);  // at the optimum: no gradient
}

TEST(GsSsimLoss, GradientMatchesFiniteDifferences) {
  const cv::Mat a = random_image(32, 24, 3), b = random_image(32, 24, 4);
  cv::Mat grad, unused, a64, b64;
  SsimLoss loss;
  loss.value_and_gradient(a, b, grad);
  // The differences in double precision: in float, a step's change of the mean drowns in rounding.
  a.convertTo(a64, CV_64FC3), b.convertTo(b64, CV_64FC3);
  // Interior pixels and at the border (the reflected window).
  for (const cv::Point p : {cv::Point(15, 12), cv::Point(7, 20), cv::Point(0, 0), cv::Point(31, 5)})
    for (int c = 0; c < 3; ++c) {
      const double h = 1e-4;
      cv::Mat up = a64.clone(), down = a64.clone();
      up.at<cv::Vec3d>(p)[c] += h, down.at<cv::Vec3d>(p)[c] -= h;
      const double numeric = (loss.value_and_gradient(up, b64, unused) - loss.value_and_gradient(down, b64, unused)) / (2 * h);
      const double analytic = grad.at<cv::Vec3f>(p)[c];
      EXPECT_NEAR(analytic, numeric, 0.01 * std::abs(numeric) + 1e-7) << "pixel " << p << " channel " << c;
    }
}

}  // namespace
}  // namespace chatsim::render::gs
