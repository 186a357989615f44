#pragma once
// Exemplar-based inpainting (after Criminisi, Perez and Toyama 2004): holes are filled patch by
// patch from the known image, the fill front advancing first where confidence is high and where
// strong edges (lane markings, kerbs) meet it, so straight structures continue into the hole.
#include <opencv2/core.hpp>

namespace chatsim::render::inpaint {

struct ExemplarOptions {
  int patch = 9;              // odd patch side, pixels
  int search_radius = 80;     // candidate sources within this many pixels of the target (0: all)
};

// image: CV_32FC3; hole: CV_8UC1, non-zero where to fill. Returns the filled image.
cv::Mat exemplar_inpaint(const cv::Mat& image, const cv::Mat& hole, const ExemplarOptions& options = {});

}  // namespace chatsim::render::inpaint
