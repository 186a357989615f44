#pragma once
// Evaluating the lighting estimate on an HDR panorama: the three front cameras of a car (50
// degree field of view, 40 degrees apart) record LDR crops of it at several headings (auto
// exposure, clipping, sRGB OETF), the estimator sees only those, and its sun is compared with
// the panorama's own peak: angular error, and the log10 error of the peak's intensity (the
// irradiance of the 5-degree cap around the peak above its surroundings). Each heading also
// reports what the sky alone says (probe_clear_sky at the panorama's sun): whether a search
// over the sky's fit could find the sun at all.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"
#include "render/env_map.hpp"

namespace chatsim::render::light {

struct PanoramaPeak {
  Eigen::Vector3f direction;
  double irradiance = 0;   // of the cap above its ring's level
};
PanoramaPeak panorama_peak(const EnvMap& panorama);

// Whether the panorama's own sun can be trusted for intensity. An HDRI merged from too few
// exposures clips its sun (blender-data's courtyard peaks at 55 while its sunlit walls are
// 25-30), and then sunlit surfaces are brighter than its light could make them: no diffuse
// surface is brighter than a white one facing where the panorama sends the most light (its
// irradiance over pi). This is the share of the sphere below the horizon above that bound. It
// proves clipping only where sunlit pale surfaces show it (a dark lawn under a clipped sun
// passes). Measured on blender-data: courtyard 4.7 %; sunset 0.45 %, the low sun's glitter on
// the water below it (specular, so allowed); sunrise 0.09 %; city and forest 0.006 %.
double overbright_ground_share(const EnvMap& panorama);
inline constexpr double kClippedSunGroundShare = 0.015;

// The crops' default width (px), for `eval light` and `bench light` alike: the estimate depends
// on it (its masks and blobs are measured in pixels; on blender-data's five panoramas the median
// error was 42.9 deg at 320 and 50.5 at 480), so the two commands must agree.
inline constexpr int kDefaultCropWidth = 320;

// One result per heading, and their medians. With save_dir, the LDR crops the estimator saw are
// written there (<name>-<heading>.png: left, front and right side by side) for a person to look at.
nlohmann::json evaluate_on_panorama(const EnvMap& panorama, const std::string& name, int headings = 8, int width = kDefaultCropWidth,
                                    const std::string& save_dir = "");

// Every panorama file (EXR or HDR) through evaluate_on_panorama, with the medians over all their
// headings (the intensity's over panoramas whose sun is not clipped; with them too in
// "median_log10_intensity_error_with_clipped"; the angle's and the time's also over the
// headings with the sun in a crop and those without), the targets, and the baseline measured
// in the same run: a fixed guess (the sun 45 degrees up, straight ahead of the car).
// `progress` gets one line per panorama. Throws on a file that does not read, naming it.
nlohmann::json evaluate_panoramas(const std::vector<std::string>& files, int headings, int width, const std::string& save_dir = "",
                                  const std::function<void(const std::string&)>& progress = nullptr);

// The estimate on a scene whose sky is known (the demo scene's ground_truth/sky.json), with the
// scene's own cameras, vehicles and their shadows: the sun's angular error and log10 intensity
// error on every `every`-th frame, and their medians. Throws naming the file when the scene has
// no ground-truth sky.
// Also the estimate the agents use, from `clip_frames` frames spread over the clip ("clip").
nlohmann::json evaluate_on_scene(const scene::Scene& scene, int every = 5,
                                 const std::function<void(const std::string&)>& progress = nullptr, int clip_frames = 4);

}  // namespace chatsim::render::light
