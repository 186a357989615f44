#pragma once
// Exemplar-based inpainting (after Criminisi, Perez and Toyama 2004): holes are filled patch by
// patch from the known image, the fill front advancing first where confidence is high and where
// strong edges (lane markings, kerbs) meet it, so straight structures continue into the hole.
#include <opencv2/core.hpp>

namespace chatsim::render::inpaint {

struct ExemplarOptions {
  int patch = 9;              // odd patch side, pixels
  int search_radius = 80;     // candidate sources within this many pixels of the target (0: all)
  // > 0: sources only beside the target, within a cone |dy| <= patch/2 + slope * |dx|. Behind a
  // removed roadside object the scene runs in near-horizontal bands (kerb, pavement, hedge,
  // facade): copying from beside keeps each band at its height, where copying from below grows
  // the pavement up into the hedge.
  double beside_slope = 0;
};

// image: CV_32FC3; hole: CV_8UC1, non-zero where to fill. `no_source` (CV_8UC1, optional):
// pixels no copied patch may contain (what must not spread into the hole). Returns the filled
// image.
cv::Mat exemplar_inpaint(const cv::Mat& image, const cv::Mat& hole, const ExemplarOptions& options = {},
                         const cv::Mat& no_source = cv::Mat());

}  // namespace chatsim::render::inpaint
