#pragma once
// Matching a fill's brightness to the image around it. A fill gathered from other views (the
// ground map, the captured sources) or rendered by the field is close in colour but rarely in
// level: the views differ in exposure and noise, the field is softer. A level step along the
// mask's outline reads as a pasted patch. The step is measured just inside and just outside the
// outline (smoothed log radiance, so a gain), and spread over the mask smoothly from there (a
// push-pull membrane), as a Poisson blend would, without its bleeding: outline points where the
// two sides differ by more than a gain (a kerb, another car the outline passes) are left out.
#include <opencv2/core.hpp>

namespace chatsim::render::inpaint {

struct SeamOptions {
  int ring_px = 3;            // width of the band measured on either side of the outline
  double smooth_px = 4;       // Gaussian sigma over each band (averages the capture's noise)
  double max_step = 0.6;      // |log ratio| above this: content differs there, not the level
  double max_gain = 0.4;      // the applied |log gain| is clamped to this
};

// The mean of `value` (CV_32F, any channels) over the pixels of `mask` (CV_8UC1) near each pixel:
// a Gaussian of `sigma` px, normalised by how much of the mask it reached (written to
// `support`, CV_32FC1, when given).
cv::Mat mean_over_mask(const cv::Mat& value, const cv::Mat& mask, double sigma, cv::Mat* support = nullptr);

// Scales `filled` (CV_32FC3 radiance) inside `mask` (CV_8UC1) toward the level of `original`
// just outside it. Returns the number of outline pixels used.
int harmonize_fill(cv::Mat& filled, const cv::Mat& original, const cv::Mat& mask, const SeamOptions& options = {});

}  // namespace chatsim::render::inpaint
