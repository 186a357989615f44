// chatsim scene info: validate a scene directory and summarise it.
#include <filesystem>
#include <iostream>

#include <spdlog/spdlog.h>

#include "common/import/nuscenes_import.hpp"
#include "common/scene/demo_layout.hpp"
#include "common/scene/scene.hpp"
#include "common/scene/scene_summary.hpp"
#include "common/util/exit_codes.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct SceneInfoArgs {
  std::string dir;
  bool json = false;
};

int run_info(const SceneInfoArgs& a) {
  try {
    const auto scene = scene::load_scene(a.dir);
    const auto summary = scene::summarize(scene);
    if (a.json) std::cout << summary.dump(1) << "\n";
    else std::cout << scene::summary_text(summary);
    return exit_code::kOk;
  } catch (const scene::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
}

struct DemoArgs {
  std::string out;
  uint64_t seed = 1;
  int frames = 40;
  bool layout_only = false;
};

int run_demo(const DemoArgs& a) {
  if (!a.layout_only) {
    std::cerr << "error: rendering the demo scene's images (Embree path tracing, sky, ground truth) is not built yet "
                 "(issue #4); run with --layout-only for the street layout, enough for every decision\n";
    return exit_code::kUsage;
  }
  scene::DemoOptions o;
  o.seed = a.seed;
  o.frames = a.frames;
  const auto s = scene::demo_layout(o);
  // Written beside the target and renamed when complete, so an interrupted run leaves nothing half-written.
  const std::filesystem::path out = std::filesystem::absolute(a.out).lexically_normal();
  const std::filesystem::path tmp = out.string() + ".tmp";
  std::filesystem::remove_all(tmp);
  scene::save_scene(s, tmp);
  std::filesystem::remove_all(out);
  std::filesystem::rename(tmp, out);
  std::cout << "wrote " << out.string() << ": " << s.frames.size() << " frames, " << s.objects.size() << " objects, "
            << s.lanes.lanes().size() << " lanes (seed " << a.seed << ")\n";
  return exit_code::kOk;
}

struct ImportArgs {
  import::NuScenesOptions options;
  std::string cameras;
  std::string out;
  bool no_lidar = false;
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
  try {
    const auto s = import::import_nuscenes(a.options, a.out, [](int done, int total, const std::string& what) {
      std::cerr << "\r  " << what << " " << done << "/" << total << std::flush;
      if (done == total) std::cerr << "\n";
    });
    int colored = 0;
    for (const auto& o : s.objects) colored += o.color_rgb ? 1 : 0;
    std::cout << "wrote " << a.out << ": " << s.frames.size() << " frames, " << s.cameras.size() << " cameras, "
              << s.objects.size() << " objects (" << colored << " with an estimated colour), lanes derived from the ego path\n";
    return exit_code::kOk;
  } catch (const import::ImportError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kFailure;
  }
}

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
  auto* demo = scene->add_subcommand("demo", "Generate the procedural demo street (seeded). Today only its layout "
                                             "(--layout-only): lanes, objects, rig, ego path; images come with issue #4");
  demo->add_option("--out", demo_args->out, "output scene directory (replaced)")->required();
  demo->add_option("--seed", demo_args->seed, "random seed (same seed, same scene)");
  demo->add_option("--frames", demo_args->frames, "number of frames at 10 Hz")->check(CLI::Range(2, 10000));
  demo->add_flag("--layout-only", demo_args->layout_only, "write the layout only (no images)");
  demo->callback([demo_args, &result] { result = run_demo(*demo_args); });
  auto* import_cmd = scene->add_subcommand("import", "Convert another dataset's scene to ours");
  import_cmd->require_subcommand(1);
  auto import_args = std::make_shared<ImportArgs>();
  auto* nus = import_cmd->add_subcommand("nuscenes", "One nuScenes scene: per-image ego poses, calibration, key-frame "
                                                     "LiDAR, boxes as tracks, vehicle colours, lanes derived from the ego path");
  nus->add_option("--dataroot", import_args->options.dataroot, "folder with <version>/ tables and samples/")->required();
  nus->add_option("--version", import_args->options.version, "table folder, e.g. v1.0-mini");
  nus->add_option("--scene", import_args->options.scene, "scene name, e.g. scene-0916")->required();
  nus->add_option("--cameras", import_args->cameras, "comma-separated channels (default CAM_FRONT,CAM_FRONT_LEFT,CAM_FRONT_RIGHT)");
  nus->add_option("--out", import_args->out, "output scene directory (replaced)")->required();
  nus->add_flag("--no-lidar", import_args->no_lidar, "skip the LiDAR point clouds");
  nus->callback([import_args, &result] { result = run_import(*import_args); });
}

}  // namespace chatsim::cli
