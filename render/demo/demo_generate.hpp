#pragma once
// The embedded default scene: the demo street rendered by path tracing as a three-camera car
// records it, with the traps real captures have (per-camera exposure, trigger-time pose
// offsets, calibration error, sensor noise, sparse LiDAR), plus the ground truth a capture
// cannot have (held-out and shifted views, clean plates without each object, depth, the sky).
#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "common/scene/demo_layout.hpp"
#include "render/demo/demo_world.hpp"

namespace chatsim::render::demo {

struct ViewShift {
  std::string name;             // e.g. "left_1m"
  Eigen::Vector3d ego_offset;   // metres in the ego frame (x ahead, y left, z up)
};

struct DemoRenderOptions {
  scene::DemoOptions layout;
  WorldOptions world;
  int spp = 4;                  // captured images
  int max_depth = 2;
  // Ground-truth views (no sensor noise; denoised). At 6 samples they kept enough path-tracing
  // noise to cost a model scored against them 1.8 dB and 0.18 SSIM (seed 1, 2026-12-03); at 64,
  // 0.3 dB and 0.037 SSIM next to 256 samples (2026-12-04), which take 64 s a view on 2 cores.
  int truth_spp = 256;
  // Per camera (front, front_left, front_right): exposure relative to the automatic one, and
  // when each fires relative to its frame.
  std::vector<double> exposure_scale{1.0, 1.3, 0.8};
  std::vector<double> trigger_offset_ms{0, 12, -9};
  double trigger_jitter_ms = 2;
  double calibration_error_deg = 0.3;  // rotation error of the recorded side-camera extrinsics
  double noise_scale = 1.0;            // sensor noise (0: none)
  bool record_exposure = true;         // false: exposure_s unknown in scene.json
  std::string image_format = "jpg";    // jpg (quality 95, as cameras store them) or png (lossless)
  bool lidar = true;
  bool clean_plates = true;
  int plate_every = 4;          // clean plates on frames with index % plate_every == 0
  int plate_min_pixels = 400;   // objects smaller than this in an image get no plate there
  bool truth_views = true;
  int holdout_every = 8, holdout_phase = 4;  // frames with index % every == phase: clean views
  std::vector<int> shifted_frames{12, 28};
  std::vector<ViewShift> shifts{{"left_1m", {0, 1, 0}}, {"right_1m", {0, -1, 0}}, {"up_1m", {0, 0, 1}},
                                {"ahead_3m", {3, 0, 0}}};
  bool force_output = false;    // replace a chatsim output of another kind at `out` (--force)
  // Stage name and 0..1 of the whole job.
  std::function<void(const std::string&, double)> progress;
};

// The small preset for tests: 160 x 106 pixels, 8 frames, fewer samples.
DemoRenderOptions small_demo_options(uint64_t seed);

struct DemoReport {
  int images = 0, plates = 0, views = 0, lidar_frames = 0;
  double seconds = 0;
  double exposure_s = 0;        // the automatic exposure, before per-camera scales
};

// Renders into `out`: new, empty or a scene chatsim wrote (common/util/output_dir.hpp), written
// under a temporary name beside it and swapped in when complete. Throws OutputDirError for any
// other folder, before rendering.
DemoReport generate_demo_scene(const DemoRenderOptions& options, const std::filesystem::path& out);

}  // namespace chatsim::render::demo
