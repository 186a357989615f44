// Exemplar inpainting continues structure (stripes, like lane markings) into a hole, where
// diffusion (Telea) only blurs it; copying from beside keeps horizontal bands at their height;
// excluded pixels are never copied.
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

cv::Mat row_band(int h, int w, int y0, int y1) {
  cv::Mat m(h, w, CV_8U, cv::Scalar(0));
  m.rowRange(y0, y1).setTo(255);
  return m;
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

// A roadside seen from the side, as behind a parked car: a dark textured hedge above a pale
// pavement band above the road. A hole over the hedge's foot is filled band by band when
// sources come from beside it; from anywhere near, the pale pavement grows up into the hedge.
TEST(ExemplarInpaint, SourcesBesideTheHoleKeepEachBandAtItsHeight) {
  const int w = 200, h = 90, hedge_end = 50, pavement_end = 60;
  cv::Mat truth(h, w, CV_32FC3);
  cv::RNG rng(7);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Leaves: mostly dark, a few lit ones as bright as the pavement.
      const float u = float(rng.uniform(0.0, 1.0));
      const float v = y < hedge_end ? 0.05f + 0.6f * u * u * u * u : y < pavement_end ? 0.55f + 0.1f * u : 0.3f + 0.05f * u;
      truth.at<cv::Vec3f>(y, x) = {v * 0.8f, v, v * 0.7f};
    }
  cv::Mat hole(truth.size(), CV_8U, cv::Scalar(0));
  cv::rectangle(hole, cv::Rect(60, 25, 80, 45), 255, cv::FILLED);  // rows 25-69: hedge, pavement, road
  cv::Mat damaged = truth.clone();
  damaged.setTo(cv::Scalar::all(0), hole);
  const cv::Mat hedge_in_hole = hole & row_band(h, w, 0, hedge_end - 4);
  // How far the hedge's mean level in the hole is from the truth's.
  const auto hedge_error = [&](double slope) {
    const cv::Mat out = chatsim::render::inpaint::exemplar_inpaint(damaged, hole, {7, 80, slope});
    return std::abs(cv::mean(out, hedge_in_hole)[1] - cv::mean(truth, hedge_in_hole)[1]);
  };
  const double beside = hedge_error(0.1), anywhere = hedge_error(0);
  // The hedge's level in the hole (its mean is 0.17, the pavement's 0.6): 0.003 from beside,
  // 0.026 from anywhere near (a pavement patch in the hedge).
  EXPECT_LT(beside, 0.01);
  EXPECT_LT(beside, anywhere / 3);
}

// A removed car beside a bus that stays: the bus's pixels are no source, so none of its colour
// spreads into what stood behind the car.
TEST(ExemplarInpaint, NoPatchComesFromWhereSourcesAreExcluded) {
  const int w = 120, h = 60;
  cv::Mat image(h, w, CV_32FC3);
  cv::RNG rng(3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = 0.2f + 0.1f * float(rng.uniform(0.0, 1.0));  // grey street
      image.at<cv::Vec3f>(y, x) = {v, v, v};
    }
  const cv::Rect bus(70, 10, 50, 45), car(40, 20, 30, 30);  // the car's hole touches the bus
  image(bus).setTo(cv::Scalar(0.9, 0.7, 0.1));
  cv::Mat car_hole(h, w, CV_8U, cv::Scalar(0)), bus_mask(h, w, CV_8U, cv::Scalar(0));
  car_hole(car).setTo(255);
  bus_mask(bus).setTo(255);
  const auto yellow_share = [&](const cv::Mat& no_source) {
    const cv::Mat out = chatsim::render::inpaint::exemplar_inpaint(image, car_hole, {7, 40, 0.1}, no_source);
    int yellow = 0;
    for (int y = car.y; y < car.y + car.height; ++y)
      for (int x = car.x; x < car.x + car.width; ++x) yellow += out.at<cv::Vec3f>(y, x)[2] < 0.15f && out.at<cv::Vec3f>(y, x)[0] > 0.5f;
    return double(yellow) / car.area();
  };
  EXPECT_GT(yellow_share(cv::Mat()), 0.05) << "with the bus as a source, some of it is copied";
  EXPECT_EQ(yellow_share(bus_mask), 0.0);
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
