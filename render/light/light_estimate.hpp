#pragma once
// Lighting estimation from a car's LDR camera images: an HDR sky dome with a sun, in the scene's
// radiance units. Sky pixels (bright, smooth, above the horizon, reached from the top of the
// image and not going on below the horizon, clipped ones as lower bounds) are fitted by a
// Preetham clear sky or a CIE overcast sky; the sun's direction is searched, scoring that fit together with the shadows labelled
// boxes would cast on the ground (how much darker the predicted shadow is, and how well its
// outline fits the dark ground; boxes matched to the views of their own instant, so several
// instants of a clip add up), and a visible sun blob is taken where the fit agrees with it;
// its intensity from the lit-to-shadow contrast on the ground, else from the fitted sky.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"
#include "render/env_map.hpp"
#include "render/light/shadow_casters.hpp"
#include "render/sky.hpp"

namespace chatsim::render::light {

struct LightView {
  scene::Camera camera;
  Eigen::Isometry3d camera_to_world;  // world z up
  cv::Mat rgb;                        // CV_8UC3, RGB
  double exposure = 1.0;              // seconds (1: unknown)
  int frame = -1;                     // which instant (boxes are matched to views of theirs); -1: any
};

struct LightEstimate {
  bool sunny = true;
  SkyParams sky;                      // the fitted model (sun direction, turbidity / overcast)
  float scale = 1;                    // the model's radiance multiplier that fits the images
  Rgb sun_radiance = Rgb::Zero();
  std::string sun_cue;                // "visible", "shadows", "sky_gradient", "none"
  // Mean squared log error on sky pixels (each capped at log 1.5 where vehicles were measured);
  // none without an unclipped sky pixel. to_json prints its root, or null.
  std::optional<double> fit_error;
  int sky_pixels = 0;

  // The dome without the sun disc (below the horizon: a diffuse ground lit by it).
  EnvMap dome(int width = 256, int height = 128) const;
  // The contract's JSON (SCENE_FORMAT.md, lighting output).
  nlohmann::json to_json(const std::string& sky_exr) const;
};

LightEstimate estimate_light(const std::vector<LightView>& views, const std::vector<GroundBox>& boxes = {});

// What the sky alone says about the sun, for evaluation against a known sun: the clear
// (Preetham) sky fitted to the sky samples estimate_light fits (without vehicles), at a given
// sun direction and at the best direction of a 5-degree grid, each at its best turbidity.
// Where the given (true) sun fits worse than the grid's best, no search over the sky's fit
// alone can find it.
struct SkyFitProbe {
  std::optional<double> rms_at;    // root mean squared log error at the given direction (none: no unclipped sky)
  std::optional<double> rms_best;  // ... at the grid's best direction
  Eigen::Vector3f best_direction = Eigen::Vector3f::UnitZ();
};
SkyFitProbe probe_clear_sky(const std::vector<LightView>& views, const Eigen::Vector3f& sun);

// The views and boxes of one frame of a scene (all its cameras).
std::vector<LightView> scene_light_views(const scene::Scene& scene, int frame);
std::vector<GroundBox> scene_ground_boxes(const scene::Scene& scene, int frame);

// Bumped when the estimator changes what it finds for the same scene: caches of estimates key
// on it (1: the clip's frames, shadows scored by outline agreement; 2: a low sun's disc found
// inside a glow that clips one channel; 3: cars cast their shadows as cars, not as boxes; 4: a
// bright region going on below the horizon is not sky, and a mostly clipped sky beside
// shadowless vehicles does not say sunny; 5: with vehicles measured, the sky fits are robust:
// scale and cost from the samples within a factor 1.5 of the model).
inline constexpr int kLightEstimatorVersion = 5;

// A scene's light, from `frames` instants spread over its clip (the sun does not move in a
// clip; every instant adds vehicles whose shadows are measurable).
LightEstimate estimate_scene_light(const scene::Scene& scene, int frames = 4);
// The frames that estimate uses.
std::vector<int> scene_light_frames(const scene::Scene& scene, int frames = 4);

// Which pixels of a view show the sky (CV_8UC1, 255 = sky).
cv::Mat sky_mask(const LightView& view);

}  // namespace chatsim::render::light
