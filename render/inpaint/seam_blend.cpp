#include "render/inpaint/seam_blend.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace chatsim::render::inpaint {
namespace {

cv::Mat log_luma(const cv::Mat& rgb) {
  cv::Mat luma;
  cv::transform(rgb, luma, cv::Matx13f(1.f / 3, 1.f / 3, 1.f / 3));
  cv::Mat out;
  cv::log(cv::max(luma, 1e-4), out);
  return out;
}

// A smooth field through sparse samples (value where weight > 0): averages pulled down a
// pyramid, then pushed back up into the gaps.
cv::Mat push_pull(const cv::Mat& value, const cv::Mat& weight) {
  std::vector<cv::Mat> v{value.mul(weight)}, w{weight.clone()};
  while (std::min(v.back().rows, v.back().cols) > 4) {
    cv::Mat vd, wd;
    cv::pyrDown(v.back(), vd);
    cv::pyrDown(w.back(), wd);
    v.push_back(vd), w.push_back(wd);
  }
  cv::Mat est = v.back() / cv::max(w.back(), 1e-8);
  for (int l = int(v.size()) - 2; l >= 0; --l) {
    cv::Mat up;
    cv::pyrUp(est, up, v[size_t(l)].size());
    const cv::Mat own = v[size_t(l)] / cv::max(w[size_t(l)], 1e-8);
    cv::Mat conf = cv::min(w[size_t(l)] * 4.0, 1.0);
    est = own.mul(conf) + up.mul(1.0 - conf);
  }
  return est;
}

}  // namespace

cv::Mat mean_over_mask(const cv::Mat& value, const cv::Mat& mask, double sigma, cv::Mat* support) {
  cv::Mat w, blurred_w;
  mask.convertTo(w, CV_32F, 1.0 / 255);
  cv::GaussianBlur(w, blurred_w, cv::Size(0, 0), sigma);
  if (support != nullptr) *support = blurred_w;
  if (value.channels() > 1) {
    cv::merge(std::vector<cv::Mat>(size_t(value.channels()), w), w);
    cv::merge(std::vector<cv::Mat>(size_t(value.channels()), blurred_w), blurred_w);
  }
  cv::Mat vw = value.mul(w);
  cv::GaussianBlur(vw, vw, cv::Size(0, 0), sigma);
  return vw / cv::max(blurred_w, 1e-6);
}

int harmonize_fill(cv::Mat& filled, const cv::Mat& original, const cv::Mat& mask, const SeamOptions& o) {
  cv::Rect roi = cv::boundingRect(mask);
  if (roi.empty()) return 0;
  const int pad = o.ring_px + int(std::ceil(3 * o.smooth_px)) + 2;
  roi = cv::Rect(roi.x - pad, roi.y - pad, roi.width + 2 * pad, roi.height + 2 * pad) & cv::Rect(0, 0, mask.cols, mask.rows);
  const cv::Mat m = mask(roi);
  const cv::Mat k = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * o.ring_px + 1, 2 * o.ring_px + 1));
  cv::Mat eroded, grown;
  cv::erode(m, eroded, k, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::dilate(m, grown, k);
  const cv::Mat inner = m & ~eroded, outer = grown & ~m;
  cv::Mat in_support, out_support;
  const cv::Mat in_level = mean_over_mask(log_luma(filled(roi)), inner, o.smooth_px, &in_support);
  // Outside, only what is like the fill up to a gain: a car beside the hole is not its level.
  const cv::Mat out_log = log_luma(original(roi));
  const cv::Mat alike = (cv::abs(out_log - in_level) <= o.max_step) & (in_support >= 0.05f);
  const cv::Mat out_level = mean_over_mask(out_log, outer & alike, o.smooth_px, &out_support);
  // The level step at each inner outline pixel with both sides measured and alike in content.
  const cv::Mat step = out_level - in_level;
  cv::Mat weight(m.size(), CV_32F, cv::Scalar(0));
  int used = 0;
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x) {
      if (!inner.at<uchar>(y, x) || in_support.at<float>(y, x) < 0.05f || out_support.at<float>(y, x) < 0.05f) continue;
      if (std::abs(step.at<float>(y, x)) > o.max_step) continue;
      weight.at<float>(y, x) = 1;
      ++used;
    }
  if (used == 0) return 0;
  const cv::Mat gain_log = push_pull(step, weight);
  cv::Mat f = filled(roi);
  for (int y = 0; y < m.rows; ++y)
    for (int x = 0; x < m.cols; ++x)
      if (m.at<uchar>(y, x)) f.at<cv::Vec3f>(y, x) *= std::exp(std::clamp(gain_log.at<float>(y, x), float(-o.max_gain), float(o.max_gain)));
  return used;
}

}  // namespace chatsim::render::inpaint
