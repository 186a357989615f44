#pragma once
// The shadow cue of the light estimator: how much darker the ground is where labelled boxes'
// shadows would fall for a candidate sun than where they would not.
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "render/light/light_estimate.hpp"

namespace chatsim::render::light {

struct ShadowCue {
  double score = 0;     // mean log(lit / shadow) over the boxes that could be measured (capped)
  double evidence = 0;  // their sum, each weighed by its outline's agreement, per instant
  double ratio = 1;     // median lit / shadow
  int boxes = 0;
};

// How much darker the ground is where boxes would cast their shadows for a sun direction than
// where they would for the mirrored sun (same distance from the box, other side): the light
// the box itself hides from the sky cancels out, the sun's shadow does not; and darker than the
// ground just around it.
// Masks cover only the boxes' surroundings: this runs for thousands of candidate suns.
ShadowCue shadow_cue(const std::vector<LightView>& views, const std::vector<cv::Mat>& gray, const std::vector<cv::Mat>& below,
                     const std::vector<GroundBox>& boxes, const Eigen::Vector3d& sun, int instants);

}  // namespace chatsim::render::light
