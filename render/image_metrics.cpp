#include "render/image_metrics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace chatsim::render {

double psnr(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
  if (a.size() != b.size() || a.type() != b.type()) throw std::invalid_argument("psnr: images differ in size or type");
  cv::Mat d;
  cv::absdiff(a, b, d);
  d.convertTo(d, CV_64F);
  d = d.mul(d);
  const cv::Scalar s = mask.empty() ? cv::mean(d) : cv::mean(d, mask);
  const double mse = (s[0] + s[1] + s[2]) / 3;
  return mse <= 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
}

void ssim_window_mean(const cv::Mat& in, cv::Mat& out) { cv::GaussianBlur(in, out, cv::Size(11, 11), 1.5, 1.5, cv::BORDER_REFLECT); }

double ssim(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
  if (a.size() != b.size() || a.type() != b.type()) throw std::invalid_argument("ssim: images differ in size or type");
  const double c1 = std::pow(0.01 * 255, 2), c2 = std::pow(0.03 * 255, 2);
  cv::Mat x, y;
  a.convertTo(x, CV_32F);
  b.convertTo(y, CV_32F);
  auto blur = [](const cv::Mat& m) {
    cv::Mat o;
    ssim_window_mean(m, o);
    return o;
  };
  const cv::Mat mx = blur(x), my = blur(y);
  const cv::Mat sxx = blur(x.mul(x)) - mx.mul(mx), syy = blur(y.mul(y)) - my.mul(my), sxy = blur(x.mul(y)) - mx.mul(my);
  const cv::Scalar k1 = cv::Scalar::all(c1), k2 = cv::Scalar::all(c2);  // every channel, not just the first
  cv::Mat num = (2 * mx.mul(my) + k1).mul(2 * sxy + k2);
  cv::Mat den = (mx.mul(mx) + my.mul(my) + k1).mul(sxx + syy + k2);
  cv::Mat map;
  cv::divide(num, den, map);
  const cv::Scalar s = mask.empty() ? cv::mean(map) : cv::mean(map, mask);
  double sum = 0;
  for (int c = 0; c < a.channels(); ++c) sum += s[c];
  return sum / a.channels();
}

}  // namespace chatsim::render
