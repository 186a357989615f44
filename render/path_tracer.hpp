#pragma once
// Path tracing with Embree: next-event estimation of the sun (a small, very bright disc,
// sampled explicitly) and of the sky map (importance sampled), combined with BSDF sampling by
// multiple importance sampling. Renders a whole camera view or a region of it, with alpha,
// depth and, where primary rays meet the shadow catcher, the ratio of light that inserted
// objects leave on the ground.
#include <cstdint>
#include <functional>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"
#include "render/env_map.hpp"
#include "render/ray_scene.hpp"
#include "render/sampling.hpp"
#include "render/sky.hpp"

namespace chatsim::render {

struct Lighting {
  const EnvMap* sky = nullptr;          // the sky without the sun disc (may be null)
  Eigen::Vector3f sun_direction = Eigen::Vector3f::UnitZ();
  Rgb sun_radiance = Rgb::Zero();       // zero: no sun
  float sun_cos_max = 1.0f;             // cos of the disc's half-angle

  bool has_sun() const { return sun_radiance.maxCoeff() > 0; }
  float sun_pdf() const { return 1.0f / cone_solid_angle(sun_cos_max); }
  static Lighting from_sky(const Sky& sky, const EnvMap& map);
};

struct RenderSettings {
  int spp = 16;                  // samples per pixel (stratified)
  int max_depth = 4;             // bounces
  uint64_t seed = 1;
  float shutter_open = 0.5f;     // instance time (0..1) at the shutter's opening and closing:
  float shutter_close = 0.5f;    // equal values mean no motion blur
  bool include_sky = true;       // primary rays that miss everything see the sky
  int catcher_light_samples = 2; // light samples per pixel sample on the shadow catcher
  int catcher_early_stop = 0;    // >0: a pixel whose first this-many samples all met the catcher,
                                 // every shadow ray unblocked, stops there (open ground: lit)
  float clamp_indirect = 0;      // >0: limit on one bounce's contribution (fireflies)
  bool denoise = false;          // smooth the diffuse sky and bounce light (render/denoise.hpp)
  int threads = 0;               // 0: all cores
  std::function<void(float)> progress;  // 0..1; called by one worker at a time
};

struct RenderedView {
  cv::Rect region;      // within the full image
  cv::Mat radiance;     // CV_32FC3, RGB, premultiplied by coverage when the sky is excluded
  cv::Mat alpha;        // CV_32FC1: share of samples that met geometry other than the catcher
  cv::Mat depth;        // CV_32FC1: z-depth (metres, camera axis) at the pixel centre; +inf: none
  cv::Mat shadow;       // CV_32FC1: light left on the catcher (1 = unshadowed)
};

RenderedView render_view(const RayScene& scene, const Lighting& lighting, const scene::Camera& camera,
                         const Eigen::Isometry3d& camera_to_world, const RenderSettings& settings,
                         cv::Rect region = {});

// The ray through a pixel position (OpenCV convention: integer coordinates are pixel centres).
Ray camera_ray(const scene::Camera& camera, const Eigen::Isometry3d& camera_to_world, float u, float v);

}  // namespace chatsim::render
