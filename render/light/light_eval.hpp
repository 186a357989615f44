#pragma once
// Evaluating the lighting estimate on an HDR panorama: the three front cameras of a car (50
// degree field of view, 40 degrees apart) record LDR crops of it at several headings (auto
// exposure, clipping, sRGB OETF), the estimator sees only those, and its sun is compared with
// the panorama's own peak: angular error, and the log10 error of the peak's intensity (the
// irradiance of the 5-degree cap around the peak above its surroundings).
#include <string>

#include <nlohmann/json.hpp>

#include "render/env_map.hpp"

namespace chatsim::render::light {

struct PanoramaPeak {
  Eigen::Vector3f direction;
  double irradiance = 0;   // of the cap above its ring's level
};
PanoramaPeak panorama_peak(const EnvMap& panorama);

// One result per heading, and their medians.
nlohmann::json evaluate_on_panorama(const EnvMap& panorama, const std::string& name, int headings = 8, int width = 480);

}  // namespace chatsim::render::light
