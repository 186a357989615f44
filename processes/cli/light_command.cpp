// chatsim light estimate / eval light: the sky dome and sun from a scene's images, and its
// accuracy on HDR panoramas.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"
#include "render/light/light_estimate.hpp"
#include "render/light/light_eval.hpp"

namespace chatsim::cli {
namespace {
namespace fs = std::filesystem;

struct EstimateArgs {
  std::string scene, out = "sky.exr";
  int frame = 0;
  int clip = 0;
};

int run_estimate(const EstimateArgs& a) {
  return exit_code_of([&] {
    prepare_output_file(a.out);  // before any work
    const auto s = scene::load_scene(a.scene);
    if (a.clip > 0) {
      // As the agents do: one estimate from frames spread over the clip.
      const auto frames = render::light::scene_light_frames(s, a.clip);
      if (frames.empty()) {
        std::cerr << "error: " << a.scene << ": no frames to estimate from\n";
        return exit_code::kUsage;
      }
      const auto est = render::light::estimate_scene_light(s, a.clip);
      est.dome().write_exr(a.out);
      auto j = est.to_json(fs::path(a.out).filename().string());
      j["frames"] = frames;
      std::cout << j.dump(1) << "\n";
      return exit_code::kOk;
    }
    const auto views = render::light::scene_light_views(s, a.frame);
    if (views.empty()) {
      std::cerr << "error: " << a.scene << ": no images at frame " << a.frame << " (chatsim scene info lists the frames)\n";
      return exit_code::kUsage;
    }
    const auto est = render::light::estimate_light(views, render::light::scene_ground_boxes(s, a.frame));
    est.dome().write_exr(a.out);
    std::cout << est.to_json(fs::path(a.out).filename().string()).dump(1) << "\n";
    return exit_code::kOk;
  });
}

struct EvalLightArgs {
  std::vector<std::string> hdri;
  int headings = 8, width = render::light::kDefaultCropWidth, every = 5;
  std::string out, save_views, scene;
  bool force = false;
};

int run_eval_light(const EvalLightArgs& a) {
  if (a.hdri.empty() && a.scene.empty()) {
    std::cerr << "error: nothing to evaluate: give --hdri FILE (an HDR panorama) and/or --scene DIR (a demo scene)\n";
    return exit_code::kUsage;
  }
  nlohmann::json report;
  std::optional<StagedOutputDir> views;
  try {
    if (!a.out.empty()) prepare_output_file(a.out);  // before any work
    if (!a.save_views.empty()) views.emplace(a.save_views, "images", a.force, "--save-views");
    report = render::light::evaluate_panoramas(a.hdri, a.headings, a.width, views ? views->path().string() : "",
                                               [](const std::string& line) { std::cerr << line << "\n"; });
    if (views) views->commit();
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
  if (!a.scene.empty()) {
    const int rc = exit_code_of([&] {
      const auto s = scene::load_scene(a.scene);
      report["scene"] = render::light::evaluate_on_scene(s, a.every, [](const std::string& line) { std::cerr << line << std::endl; });
      std::cerr << s.name << ": median sun error " << report["scene"]["median_angular_error_deg"].get<double>() << " deg (one frame), "
                << report["scene"]["clip"]["peak_angular_error_deg"].get<double>() << " deg (the clip, as the agents estimate)\n";
      return exit_code::kOk;
    });
    if (rc != exit_code::kOk) return rc;
  }
  if (!a.out.empty()) std::ofstream(a.out) << report.dump(1) << "\n";
  std::cout << report.dump(1) << "\n";
  return exit_code::kOk;
}

}  // namespace

void add_light_command(CLI::App& app, int& result) {
  auto* light = app.add_subcommand("light", "Lighting: estimate the sky dome and sun of a scene's frame or clip");
  light->require_subcommand(1);
  auto ea = std::make_shared<EstimateArgs>();
  auto* est = light->add_subcommand("estimate", "Estimate an HDR sky dome (EXR) and the sun from one frame's images (or, with "
                                                "--clip, several frames'); prints the lighting JSON of SCENE_FORMAT.md");
  est->add_option("--scene", ea->scene, "scene directory")->required();
  est->add_option("--frame", ea->frame, "frame index");
  est->add_option("--clip", ea->clip,
                  "estimate from this many frames spread over the clip instead of one --frame (as the agents do: 4)")
      ->check(CLI::Range(1, 64))
      ->excludes(est->get_option("--frame"));
  est->add_option("--out", ea->out, "sky dome EXR to write (replaced)")->capture_default_str();
  est->callback([ea, &result] { result = run_estimate(*ea); });
}

void add_eval_light_command(CLI::App& eval, int& result) {
  auto a = std::make_shared<EvalLightArgs>();
  auto* cmd = eval.add_subcommand("light", "Lighting estimation on HDR panoramas (the car's three front cameras see LDR "
                                           "crops at several headings) and/or a demo scene with its ground-truth sky; "
                                           "peak angular error (deg) and log10 peak intensity error");
  cmd->add_option("--hdri", a->hdri, "equirect panoramas (.exr or .hdr), z up")->check(CLI::ExistingFile);
  cmd->add_option("--scene", a->scene, "a scene with a ground-truth sky (a generated demo scene): estimated from its own "
                                       "cameras and vehicles' shadows, against ground_truth/sky.json");
  cmd->add_option("--every", a->every, "with --scene: every N-th frame")->check(CLI::Range(1, 10000));
  cmd->add_option("--headings", a->headings, "headings per panorama")->check(CLI::Range(1, 64));
  cmd->add_option("--width", a->width, "crop width in pixels")->check(CLI::Range(64, 4096));
  cmd->add_option("--out", a->out, "also write the JSON report here (replaced)");
  cmd->add_option("--save-views", a->save_views, "write the LDR crops the estimator saw to this folder (new, empty, or "
                                                 "images chatsim wrote)");
  cmd->add_flag("--force", a->force, kForceHelp);
  cmd->callback([a, &result] { result = run_eval_light(*a); });
}

}  // namespace chatsim::cli
