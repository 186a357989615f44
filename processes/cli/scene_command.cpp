// chatsim scene info: validate a scene directory and summarise it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include <spdlog/spdlog.h>

#include "common/import/nuscenes_import.hpp"
#include "common/scene/demo_layout.hpp"
#include "common/scene/scene.hpp"
#include "common/scene/scene_summary.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "common/util/progress.hpp"
#include "render/demo/demo_generate.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct SceneInfoArgs {
  std::string dir;
  bool json = false;
};

int run_info(const SceneInfoArgs& a) {
  return exit_code_of([&] {
    const auto scene = scene::load_scene(a.dir);
    const auto summary = scene::summarize(scene);
    if (a.json) std::cout << summary.dump(1) << "\n";
    else std::cout << scene::summary_text(summary);
    return exit_code::kOk;
  });
}

struct DemoArgs {
  std::string out;
  uint64_t seed = 1;
  int frames = 0;             // 0: the preset's
  bool layout_only = false;
  std::string preset = "default";
  int spp = 0;                // 0: the preset's
  int truth_spp = 0;          // 0: the preset's, at least twice spp
  bool overcast = false;
  bool hide_exposure = false;
  double noise = 1.0;
  double calibration_error_deg = 0.3;
  double trigger_offset_scale = 1.0;
  bool no_plates = false, no_lidar = false, no_views = false;
  bool force = false;
};

int run_demo_render(const DemoArgs& a) {
  render::demo::DemoRenderOptions o;
  if (a.preset == "small") o = render::demo::small_demo_options(a.seed);
  o.layout.seed = o.world.seed = a.seed;
  if (a.frames > 0) o.layout.frames = a.frames;
  if (a.spp > 0) o.spp = a.spp, o.truth_spp = std::max(o.truth_spp, 2 * a.spp);
  if (a.truth_spp > 0) o.truth_spp = a.truth_spp;
  o.world.overcast = a.overcast;
  o.record_exposure = !a.hide_exposure;
  o.noise_scale = a.noise;
  o.calibration_error_deg = a.calibration_error_deg;
  for (auto& t : o.trigger_offset_ms) t *= a.trigger_offset_scale;
  o.trigger_jitter_ms *= a.trigger_offset_scale;
  o.force_output = a.force;
  o.clean_plates = !a.no_plates;
  o.lidar = !a.no_lidar;
  o.truth_views = !a.no_views;
  ProgressBar bar("demo scene");
  o.progress = [&bar](const std::string& what, double f) { bar.update(f, what); };
  try {
    const auto r = render::demo::generate_demo_scene(o, a.out);
    bar.finish();
    std::cout << "wrote " << std::filesystem::absolute(a.out).lexically_normal().string() << ": " << r.images << " images ("
              << o.layout.width << "x" << o.layout.height << ", " << o.spp << " spp), " << r.plates << " clean plates, "
              << r.views << " ground-truth views, " << r.lidar_frames << " LiDAR sweeps in " << std::fixed
              << std::setprecision(1) << r.seconds << " s (seed " << a.seed << ")\n";
    return exit_code::kOk;
  } catch (const std::exception&) {
    bar.finish();
    throw;
  }
}

int write_demo_layout(const DemoArgs& a) {
  scene::DemoOptions o;
  o.seed = a.seed;
  if (a.frames > 0) o.frames = a.frames;
  const auto s = scene::demo_layout(o);
  // Written beside the target and swapped in when complete, so an interrupted run leaves nothing half-written.
  StagedOutputDir out(a.out, "scene", a.force);
  scene::save_scene(s, out.path());
  out.commit();
  std::cout << "wrote " << out.target().string() << ": " << s.frames.size() << " frames, " << s.objects.size() << " objects, "
            << s.lanes.lanes().size() << " lanes (seed " << a.seed << ")\n";
  return exit_code::kOk;
}

int run_demo(const DemoArgs& a) {
  return exit_code_of([&] { return a.layout_only ? write_demo_layout(a) : run_demo_render(a); });
}

struct ImportArgs {
  import::NuScenesOptions options;
  std::string cameras;
  std::string out;
  bool no_lidar = false, no_level = false, force = false;
};

int run_import(ImportArgs a) {
  if (!a.cameras.empty()) {
    a.options.cameras.clear();
    for (size_t start = 0; start <= a.cameras.size();) {
      const size_t comma = std::min(a.cameras.find(',', start), a.cameras.size());
      if (comma > start) a.options.cameras.push_back(a.cameras.substr(start, comma - start));
      start = comma + 1;
    }
  }
  a.options.lidar = !a.no_lidar;
  a.options.level_frames = !a.no_level;
  a.options.force_output = a.force;
  return exit_code_of([&] {
    std::map<int, import::FrameLevel> levels;
    const auto s = import::import_nuscenes(
        a.options, a.out,
        [](int done, int total, const std::string& what) {
          std::cerr << "\r  " << what << " " << done << "/" << total << std::flush;
          if (done == total) std::cerr << "\n";
        },
        &levels);
    int colored = 0;
    for (const auto& o : s.objects) colored += o.color_rgb ? 1 : 0;
    std::cout << "wrote " << s.dir.string() << ": " << s.frames.size() << " frames, " << s.cameras.size() << " cameras, "
              << s.objects.size() << " objects (" << colored << " with an estimated colour), lanes derived from the ego path\n";
    if (!levels.empty()) {
      double lo = 0, hi = 0, tilt = 0;
      for (const auto& [frame, l] : levels)
        lo = std::min(lo, l.height), hi = std::max(hi, l.height), tilt = std::max(tilt, std::hypot(l.slope_x, l.slope_y));
      std::cout << std::fixed << std::setprecision(2) << "levelled by the static boxes: frame heights " << lo << " to " << hi
                << " m, tilt up to " << std::atan(tilt) * 180 / M_PI << " deg\n";
    } else if (a.options.level_frames) {
      std::cout << "not levelled: too few static boxes\n";
    }
    return exit_code::kOk;
  });
}

const char* const kSceneOutHelp =
    "output scene folder: new, empty, or a scene chatsim wrote (replaced when the new one is complete); any other "
    "folder is refused";

}  // namespace

void add_scene_command(CLI::App& app, int& result) {
  auto* scene = app.add_subcommand("scene", "Scenes: inspect (info), generate the demo street (demo), import (import nuscenes)");
  scene->require_subcommand(1);
  auto args = std::make_shared<SceneInfoArgs>();
  auto* info = scene->add_subcommand("info", "Validate a scene directory and print a summary (cameras, frames, extent, "
                                             "objects by category, lanes); errors name the file and field");
  info->add_option("dir", args->dir, "scene directory")->required();
  info->add_flag("--json", args->json, "print the summary as JSON");
  info->callback([args, &result] { result = run_info(*args); });
  auto demo_args = std::make_shared<DemoArgs>();
  auto* demo = scene->add_subcommand("demo", "Generate the procedural demo street (seeded), path traced as a "
                                             "three-camera car records it, with ground truth (held-out and shifted "
                                             "views, clean plates, depth, sky); or only its layout");
  demo->add_option("--out", demo_args->out, kSceneOutHelp)->required();
  demo->add_flag("--force", demo_args->force, kForceHelp);
  demo->add_option("--seed", demo_args->seed, "random seed (same seed, same scene)");
  demo->add_option("--frames", demo_args->frames, "number of frames at 10 Hz (default: the preset's)")->check(CLI::Range(2, 10000));
  demo->add_flag("--layout-only", demo_args->layout_only, "write the layout only (no images): enough for every decision");
  demo->add_option("--preset", demo_args->preset, "default (640x426, 40 frames) or small (160x106, 8 frames; tests)")
      ->check(CLI::IsMember({"default", "small"}));
  demo->add_option("--spp", demo_args->spp, "path-tracing samples per pixel of the captured images")->check(CLI::Range(1, 4096));
  demo->add_option("--truth-spp", demo_args->truth_spp,
                   "samples per pixel of the ground-truth views (default: the preset's, 256, or twice --spp; fewer leave "
                   "path-tracing noise in them, which lowers any model's score against them)")
      ->check(CLI::Range(1, 4096));
  demo->add_flag("--overcast", demo_args->overcast, "an overcast sky (no sun) instead of a clear one");
  demo->add_flag("--hide-exposure", demo_args->hide_exposure, "leave exposure_s out of scene.json (unknown exposures)");
  demo->add_option("--noise", demo_args->noise, "sensor noise scale (0: none)")->check(CLI::Range(0.0, 20.0));
  demo->add_option("--calibration-error-deg", demo_args->calibration_error_deg,
                   "rotation error of the side cameras' recorded extrinsics")->check(CLI::Range(0.0, 20.0));
  demo->add_option("--trigger-offset-scale", demo_args->trigger_offset_scale,
                   "scale of the cameras' trigger-time offsets (0: all fire with the frame)")->check(CLI::Range(0.0, 100.0));
  demo->add_flag("--no-plates", demo_args->no_plates, "skip the clean plates");
  demo->add_flag("--no-lidar", demo_args->no_lidar, "skip the LiDAR sweeps");
  demo->add_flag("--no-views", demo_args->no_views, "skip the ground-truth views");
  demo->callback([demo_args, &result] { result = run_demo(*demo_args); });
  auto* import_cmd = scene->add_subcommand("import", "Convert another dataset's scene to ours");
  import_cmd->require_subcommand(1);
  auto import_args = std::make_shared<ImportArgs>();
  auto* nus = import_cmd->add_subcommand("nuscenes", "One nuScenes scene: per-image ego poses (each frame levelled by "
                                                     "its static boxes), calibration, key-frame LiDAR, boxes as tracks, "
                                                     "vehicle colours, lanes derived from the ego path");
  nus->add_option("--dataroot", import_args->options.dataroot, "folder with <version>/ tables and samples/")->required();
  nus->add_option("--version", import_args->options.version, "table folder, e.g. v1.0-mini");
  nus->add_option("--scene", import_args->options.scene, "scene name, e.g. scene-0916")->required();
  nus->add_option("--cameras", import_args->cameras, "comma-separated channels (default CAM_FRONT,CAM_FRONT_LEFT,CAM_FRONT_RIGHT)");
  nus->add_option("--out", import_args->out, kSceneOutHelp)->required();
  nus->add_flag("--force", import_args->force, kForceHelp);
  nus->add_flag("--no-lidar", import_args->no_lidar, "skip the LiDAR point clouds");
  nus->add_flag("--no-level", import_args->no_level,
                "keep nuScenes' ego poses as they are (all at height 0) instead of levelling each frame by its static boxes");
  nus->callback([import_args, &result] { result = run_import(*import_args); });
}

}  // namespace chatsim::cli
