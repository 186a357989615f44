#pragma once
// SSIM as a training loss: the mean SSIM of a rendered image against its target (the metric's
// window: Gaussian 11x11, sigma 1.5, each channel) and its exact gradient with respect to the
// rendered image, so a trainer can mix D-SSIM into its L1 loss as 3D Gaussian splatting does.
#include <opencv2/core.hpp>

namespace chatsim::render::gs {

class SsimLoss {
 public:
  // `pred` and `target`: CV_32FC3 (or CV_64FC3) in [0, 1], the same size. Returns the mean
  // SSIM over pixels and channels; `d_pred` receives d(mean SSIM) / d(pred).
  double value_and_gradient(const cv::Mat& pred, const cv::Mat& target, cv::Mat& d_pred);

 private:
  // Kept between calls: fresh buffers of an image's size each iteration cost page faults.
  cv::Mat mx_, my_, xx_, yy_, xy_, product_, alpha_, beta_, gamma_, blurred_alpha_, blurred_beta_, blurred_gamma_;
};

}  // namespace chatsim::render::gs
