// chatsim train / render / eval nvs: the radiance field from the command line.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "common/util/progress.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"
#include "processes/cli/train_progress.hpp"
#include "render/gs/nvs_eval.hpp"
#include "render/gs/trainer.hpp"
#include "render/image_io.hpp"
#include "common/util/preset_names.hpp"

namespace chatsim::cli {
namespace {
namespace fs = std::filesystem;

struct TrainArgs {
  std::string scene, out, preset = "fast";
  int holdout = 0, iterations = 0, max_width = 0;
  size_t max_gaussians = 0;
  float densify_threshold = 2e-4f, ssim_weight = 0, coarse_share = render::gs::TrainOptions{}.coarse_share;
  bool no_exposure = false, no_pose = false;
  uint64_t seed = 1;
};

int run_train(const TrainArgs& a) {
  scene::Scene s;
  try {
    s = scene::load_scene(a.scene);
  } catch (const scene::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
  try {
    prepare_output_file(a.out);  // before training, not after
  } catch (const OutputDirError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
  render::gs::TrainOptions o;
  o.preset = a.preset;
  o.holdout = a.holdout;
  o.max_iterations = a.iterations;
  o.max_width = a.max_width;
  o.max_gaussians = a.max_gaussians;
  o.densify_threshold = a.densify_threshold;
  o.ssim_weight = a.ssim_weight;
  o.coarse_share = a.coarse_share;
  o.exposure = !a.no_exposure;
  o.pose_refinement = !a.no_pose;
  o.seed = a.seed;
  ProgressBar bar("train");
  o.progress = train_progress(bar, o.coarse_share);
  try {
    render::gs::TrainReport r;
    const auto model = render::gs::train(s, o, &r);
    bar.finish();
    model.save(a.out);
    std::cout << nlohmann::json{{"model", fs::absolute(a.out).string()}, {"iterations", r.iterations}, {"converged", r.converged},
                                {"seconds", r.seconds}, {"train_psnr", r.train_psnr}, {"gaussians", r.gaussians},
                                {"images", r.images}, {"held_out", r.held_out}, {"resolution", {r.width, r.height}}}
                     .dump(1)
              << "\n";
    return exit_code::kOk;
  } catch (const std::invalid_argument& e) {
    bar.finish();
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  } catch (const std::exception& e) {
    bar.finish();
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kFailure;
  }
}

struct RenderArgs {
  std::string model, scene, out, view_offset = "0,0,0";
  double yaw_deg = 0;
  std::vector<int> frames;
  std::vector<std::string> cameras;
  int max_width = 0;
  bool force = false;
};

int run_render(const RenderArgs& a) {
  return exit_code_of([&] {
    StagedOutputDir out(a.out, "renders", a.force);  // whole or not at all, refused before any work
    const auto s = scene::load_scene(a.scene);
    const auto model = render::gs::RadianceField::load(a.model);
    Eigen::Vector3d offset;
    char c1, c2;
    std::istringstream in(a.view_offset);
    if (!(in >> offset.x() >> c1 >> offset.y() >> c2 >> offset.z()) || c1 != ',' || c2 != ',') {
      std::cerr << "error: --view-offset '" << a.view_offset << "': expected dx,dy,dz in metres (ego frame: ahead, left, up)\n";
      return exit_code::kUsage;
    }
    ProgressBar bar("render");
    int done = 0, total = 0;
    for (const auto& f : s.frames)
      if (a.frames.empty() || std::count(a.frames.begin(), a.frames.end(), f.index)) total += int(a.cameras.empty() ? s.cameras.size() : a.cameras.size());
    double seconds = 0;
    for (const auto& f : s.frames) {
      if (!a.frames.empty() && !std::count(a.frames.begin(), a.frames.end(), f.index)) continue;
      for (const auto& cam : s.cameras) {
        if (!a.cameras.empty() && !std::count(a.cameras.begin(), a.cameras.end(), cam.name)) continue;
        // The new view: the ego moved by the offset and turned by the yaw, cameras with it.
        const Eigen::Isometry3d pose = model.corrected_pose(s, f.index, cam.name);
        Eigen::Isometry3d ego_move = Eigen::Isometry3d::Identity();
        ego_move.translation() = offset;
        ego_move.linear() = Eigen::AngleAxisd(a.yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        const Eigen::Isometry3d ego = f.ego_to_world;
        const Eigen::Isometry3d moved = ego * ego_move * ego.inverse() * pose;
        const auto cam_r = render::gs::scaled_camera(cam, a.max_width);
        const double t = f.images.count(cam.name) ? f.images.at(cam.name).timestamp_s : f.timestamp_s;
        const auto t0 = std::chrono::steady_clock::now();
        const auto img = model.render(s, cam_r, moved, t);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        char name[64];
        std::snprintf(name, sizeof name, "%s/%06d", cam.name.c_str(), f.index);
        const float exposure = float(model.exposure(s, f.index, cam.name));
        render::write_rgb8(out.path() / (std::string(name) + ".png"), render::encode_srgb8(img.radiance, exposure));
        render::write_exr(out.path() / (std::string(name) + "_depth.exr"), img.depth);
        render::write_exr(out.path() / (std::string(name) + "_radiance.exr"), img.radiance);
        bar.update(double(++done) / total, std::string(name));
      }
    }
    bar.finish();
    out.commit();
    std::cout << "rendered " << done << " images into " << out.target().string() << " (" << std::fixed << std::setprecision(3)
              << (done ? seconds / done : 0) << " s per image)\n";
    return exit_code::kOk;
  });
}

struct NvsArgs {
  std::string scene, model, save;
  int holdout = 8, max_width = 0;
  bool no_truth = false, force = false;
};

int run_eval_nvs(const NvsArgs& a) {
  return exit_code_of([&] {
    std::optional<StagedOutputDir> save;
    if (!a.save.empty()) save.emplace(a.save, "renders", a.force, "--save");
    const auto s = scene::load_scene(a.scene);
    const auto model = render::gs::RadianceField::load(a.model);
    render::gs::NvsOptions o;
    o.holdout = a.holdout;
    o.max_width = a.max_width;
    o.ground_truth = !a.no_truth;
    o.save_dir = save ? save->path().string() : "";
    const auto r = render::gs::evaluate_nvs(model, s, o);
    if (save) save->commit();
    std::cout << r.dump(1) << "\n";
    return exit_code::kOk;
  });
}

}  // namespace

void add_eval_nvs_command(CLI::App& eval, int& result) {
  auto a = std::make_shared<NvsArgs>();
  auto* nvs = eval.add_subcommand("nvs", "Novel-view quality of a radiance field: PSNR, SSIM (Gaussian 11x11, sigma 1.5) "
                                         "and render time per image on held-out images and the demo's ground-truth "
                                         "views, as JSON");
  nvs->add_option("--scene", a->scene, "scene directory")->required();
  nvs->add_option("--model", a->model, "model file from chatsim train")->required();
  nvs->add_option("--holdout", a->holdout, "the holdout the model was trained with")->check(CLI::Range(0, 1000));
  nvs->add_option("--max-width", a->max_width, "evaluate at this width (default: the training width)");
  nvs->add_flag("--no-ground-truth", a->no_truth, "skip ground_truth/views.json");
  nvs->add_option("--save", a->save, "write the renders into this folder (new, empty, or renders chatsim wrote)");
  nvs->add_flag("--force", a->force, kForceHelp);
  nvs->callback([a, &result] { result = run_eval_nvs(*a); });
}

void add_radiance_commands(CLI::App& app, int& result) {
  auto ta = std::make_shared<TrainArgs>();
  auto* train = app.add_subcommand("train", "Train the scene's radiance field (3D Gaussians on the CPU) from its images; "
                                            "prints a JSON report");
  train->add_option("--scene", ta->scene, "scene directory")->required();
  train->add_option("--out", ta->out, "model file to write (replaced)")->required();
  train->add_option("--preset", ta->preset, "draft (a quick look), fast (up to 1800 iterations: about 8 min on 2 cores for the demo scene) or quality")->check(CLI::IsMember(preset_names()));
  train->add_option("--holdout", ta->holdout, "hold out frames with index % N == N/2 for evaluation (0: none)")->check(CLI::Range(0, 1000));
  train->add_option("--iterations", ta->iterations, "at most this many iterations (default: the preset's)")->check(CLI::Range(1, 1000000));
  train->add_option("--max-width", ta->max_width, "downscale wider images to this width (default: the preset's)")->check(CLI::Range(16, 8192));
  train->add_option("--max-gaussians", ta->max_gaussians, "at most this many Gaussians (default: the preset's)");
  train->add_option("--densify-threshold", ta->densify_threshold, "screen-space gradient (NDC) that makes a Gaussian grow")
      ->check(CLI::PositiveNumber);
  train->add_option("--ssim-weight", ta->ssim_weight, "D-SSIM's share of the image loss, (1 - w) L1 + w (1 - SSIM); 0.2 as in 3D Gaussian splatting (default 0: L1)")
      ->check(CLI::Range(0.0f, 1.0f));
  train->add_option("--coarse-share", ta->coarse_share, "share of the iterations trained at half resolution, the first ones")
      ->check(CLI::Range(0.0f, 1.0f))
      ->capture_default_str();
  train->add_flag("--no-exposure", ta->no_exposure, "ablation: ignore exposure_s and learn no exposure corrections");
  train->add_flag("--no-pose-refinement", ta->no_pose, "ablation: trust the recorded camera poses");
  train->add_option("--seed", ta->seed, "random seed");
  train->callback([ta, &result] { result = run_train(*ta); });

  auto ra = std::make_shared<RenderArgs>();
  auto* render = app.add_subcommand("render", "Render the scene's views from a radiance field, optionally moved: PNG "
                                              "(at the image's exposure), radiance and depth EXR");
  render->add_option("--model", ra->model, "model file from chatsim train")->required();
  render->add_option("--scene", ra->scene, "scene directory")->required();
  render->add_option("--out", ra->out, "output folder: new, empty, or renders chatsim wrote (replaced when the new ones are "
                                       "complete); any other folder is refused")->required();
  render->add_flag("--force", ra->force, kForceHelp);
  render->add_option("--view-offset", ra->view_offset, "dx,dy,dz: move the ego (metres: ahead, left, up)");
  render->add_option("--yaw", ra->yaw_deg, "turn the ego (degrees, left positive)");
  render->add_option("--frames", ra->frames, "frame indices (default: all)");
  render->add_option("--cameras", ra->cameras, "camera names (default: all)");
  render->add_option("--max-width", ra->max_width, "render at most this wide")->check(CLI::Range(16, 8192));
  render->callback([ra, &result] { result = run_render(*ra); });
}

}  // namespace chatsim::cli
