#pragma once
// Novel-view evaluation of a radiance field: held-out captured images (at their recorded poses
// with the learned per-camera correction) and, for the demo scene, the noise-free ground-truth
// views (at their true poses, unshifted and shifted); PSNR, SSIM and render time per image.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/gs/model.hpp"

namespace chatsim::render::gs {

struct NvsOptions {
  int holdout = 8;          // the frames a holdout of this size kept out of training
  int max_width = 0;        // evaluate at this width (0: the model's training width)
  bool ground_truth = true; // also the scene's ground_truth/views.json when present
  int threads = 0;
  std::string save_dir;     // write renders here when not empty
};

// {"sets": {name: {count, psnr, psnr_static, ssim, render_s}}, "views": [...]}; psnr_static leaves out
// where moving objects (and their shadows) are at the view's time, over the views with at least
// 5 % of their pixels left (static_count).
nlohmann::json evaluate_nvs(const RadianceField& model, const scene::Scene& scene, const NvsOptions& options);

}  // namespace chatsim::render::gs
