#pragma once
// Training a radiance field from a scene's images: Gaussians start at the LiDAR points (those
// inside a labelled box belong to that object) and on facades above the LiDAR's reach, then an
// Adam optimiser fits them, the sky, per-image exposure and per-camera and per-image pose
// corrections to the images through the sRGB OETF; Gaussians are split, cloned and pruned as
// the image error asks, and training stops when the loss stops falling.
#include <algorithm>
#include <functional>
#include <string>

#include "common/scene/scene.hpp"
#include "render/gs/model.hpp"

namespace chatsim::render::gs {

// Bumped when a change makes models trained before it wrong for the same scene (2: images
// start at the ego pose of their own timestamp, so earlier pose corrections no longer fit;
// 3: calibration refined from 2 % of training, moving shadows left out of it: better poses;
// 4: `fast` trains 1500 iterations, not 1000; 5: cameras' translations learn at a tenth of the
// rate; 6: `fast` trains 1800; 7: colour's rates fall tenfold over training). Caches of trained
// models key on it.
inline constexpr int kTrainerVersion = 7;

struct TrainOptions {
  std::string preset = "fast";      // draft | fast | quality
  int max_iterations = 0;           // 0: the preset's
  int max_width = 0;                // images wider than this are downscaled (0: the preset's)
  bool exposure = true;             // use exposure_s and learn per-image corrections
  bool pose_refinement = true;
  float pose_start = 0.2f;          // share of the iterations before each image's pose is refined
  float camera_pose_start = 0.02f;  // ... and each camera's calibration (before the field learns around its error)
  double pose_blind_pad_m = 4;      // ground this near a moving object's box does not pull the poses (its shadow)
  float coarse_share = 0.3f;        // share of the iterations trained at half resolution
  // D-SSIM's share of the image loss, (1 - w) L1 + w (1 - SSIM), as 3D Gaussian splatting mixes
  // them (w = 0.2). Off by default: on the demo's ground-truth views w = 0.2 gained 0.68 dB at
  // 600 iterations but 0.18 at 1500, where it grew a third more Gaussians and took 647 s, not 428.
  float ssim_weight = 0;
  double depth_weight = 0.1;        // LiDAR depth supervision (relative L1) against the image loss; 0: none
  int holdout = 0;                  // hold out frames with index % holdout == holdout / 2 (0: none)
  size_t max_gaussians = 0;         // 0: the preset's
  float densify_threshold = 2e-4f;  // mean screen-space gradient (NDC) above which a Gaussian grows
  uint64_t seed = 1;
  int threads = 0;
  // iteration, total, training loss (L1), PSNR of the last image (dB), Gaussians.
  std::function<void(int, int, double, double, size_t)> progress;
};

struct TrainReport {
  int iterations = 0;
  bool converged = false;
  double seconds = 0;
  double final_loss = 0;
  double train_psnr = 0;           // mean over the last 100 iterations
  size_t gaussians = 0;
  int images = 0, held_out = 0;
  int width = 0, height = 0;       // the training resolution
};

// How many of `total` iterations train at half resolution (the first ones).
inline int coarse_iterations(int total, float coarse_share) { return int(coarse_share * float(total)); }

// Share of training's work done after `it` of `total` iterations, for a progress bar's ETA: a
// coarse iteration (a quarter of the pixels) took 0.55 of a full one (demo scene, 2026-12-04:
// 0.18 s against 0.31), so counting iterations promised the end too early.
inline double training_work_done(int it, int total, float coarse_share) {
  constexpr double kCoarseCost = 0.55;
  const int coarse = coarse_iterations(total, coarse_share);
  auto work = [&](int i) { return kCoarseCost * std::min(i, coarse) + std::max(0, i - coarse); };
  return total > 0 && work(total) > 0 ? std::min(1.0, work(it) / work(total)) : 1.0;
}

// True for images a holdout of `every` keeps out of training.
inline bool held_out(int frame_index, int every) { return every > 0 && frame_index % every == every / 2; }

RadianceField train(const scene::Scene& scene, const TrainOptions& options, TrainReport* report = nullptr);

// Which of the `placed` Gaussians of the background lie on the ground within `pad_m` of a
// `moving` object's box at `time_s` (within 0.5 m of its base): there its shadow moves with it,
// which the static background cannot learn. Nonzero: left out of the camera pose's gradient,
// which the smear would pull. `moving` is moving_objects(scene); placed Gaussian j is the
// model's source[j], whose owner is -1 for the background, else its object.
std::vector<uint8_t> moving_shadow_band(const scene::Scene& scene, const std::vector<bool>& moving, const Gaussians& placed,
                                        const std::vector<int>& source, const std::vector<int>& owner, double time_s, double pad_m);

// A camera scaled to a smaller image (intrinsics follow), for training and rendering at lower
// resolution.
scene::Camera scaled_camera(const scene::Camera& camera, int max_width);

}  // namespace chatsim::render::gs
