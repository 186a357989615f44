#pragma once
// Image quality metrics on 8-bit RGB images: PSNR, and SSIM with an 11 x 11 Gaussian window
// (sigma 1.5) averaged over channels (Wang et al. 2004). An optional mask limits both.
#include <opencv2/core.hpp>

namespace chatsim::render {

double psnr(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask = cv::Mat());
double ssim(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask = cv::Mat());

// SSIM's window: the local means it takes (an 11 x 11 Gaussian, sigma 1.5, reflected at the
// border). Shared with the training loss (gs::SsimLoss) so the two measure the same thing.
void ssim_window_mean(const cv::Mat& in, cv::Mat& out);

}  // namespace chatsim::render
