// Exemplar inpainting continues structure (stripes, like lane markings) into a hole, where
// diffusion (Telea) only blurs it.
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

#include "render/inpaint/exemplar_inpaint.hpp"

namespace {

cv::Mat stripes(int w, int h) {
  cv::Mat img(h, w, CV_32FC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = (y / 4) % 2 ? 0.8f : 0.2f;
      img.at<cv::Vec3f>(y, x) = {v, v * 0.9f, v * 0.8f};
    }
  return img;
}

double mean_abs_error(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
  cv::Mat d;
  cv::absdiff(a, b, d);
  return cv::mean(d, mask)[0];
}

TEST(ExemplarInpaint, ContinuesStripesIntoAHoleBetterThanDiffusion) {
  const cv::Mat truth = stripes(80, 64);
  cv::Mat hole(truth.size(), CV_8U, cv::Scalar(0));
  cv::rectangle(hole, cv::Rect(30, 20, 18, 18), 255, cv::FILLED);
  cv::Mat damaged = truth.clone();
  damaged.setTo(cv::Scalar::all(0), hole);
  const cv::Mat ours = chatsim::render::inpaint::exemplar_inpaint(damaged, hole, {7, 40});
  cv::Mat u8, telea8, telea;
  damaged.convertTo(u8, CV_8UC3, 255);
  cv::inpaint(u8, hole, telea8, 5, cv::INPAINT_TELEA);
  telea8.convertTo(telea, CV_32FC3, 1.0 / 255);
  const double e_ours = mean_abs_error(ours, truth, hole), e_telea = mean_abs_error(telea, truth, hole);
  EXPECT_LT(e_ours, 0.05);  // stripes copied, not smeared (the stripes differ by 0.6)
  EXPECT_LT(e_ours, e_telea / 3);
  // Known pixels are left alone.
  EXPECT_EQ(mean_abs_error(ours, truth, hole == 0), 0.0);
}

TEST(ExemplarInpaint, IsDeterministic) {
  const cv::Mat truth = stripes(64, 48);
  cv::Mat hole(truth.size(), CV_8U, cv::Scalar(0));
  cv::circle(hole, {30, 24}, 9, 255, cv::FILLED);
  const cv::Mat a = chatsim::render::inpaint::exemplar_inpaint(truth, hole, {7, 20});
  const cv::Mat b = chatsim::render::inpaint::exemplar_inpaint(truth, hole, {7, 20});
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
}

}  // namespace
