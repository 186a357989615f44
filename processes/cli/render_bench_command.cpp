// chatsim bench foreground / light / deletion / nvs / e2e: the rendering methods' speed against
// their accuracy, each against a baseline measured in the same run; JSON and a PNG chart in
// bench/results/.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/chart.hpp"
#include "bench/foreground_bench.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"
#include "processes/cli/train_progress.hpp"
#include "render/gs/model.hpp"
#include "render/gs/nvs_eval.hpp"
#include "render/gs/train_config_name.hpp"
#include "render/gs/trainer.hpp"
#include "render/inpaint/deletion_eval.hpp"
#include "render/inpaint/moved_view_eval.hpp"
#include "render/light/light_eval.hpp"

namespace chatsim::cli {
namespace fs = std::filesystem;
using nlohmann::json;

void write_report(const fs::path& file, const json& report) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  std::ofstream(file.string() + ".tmp") << report.dump(1) << "\n";
  fs::rename(file.string() + ".tmp", file);
  std::cerr << "wrote " << file.string() << "\n";
}

namespace {

struct ForegroundArgs {
  std::string out = "bench/results/foreground.json";
  bool quick = false;
};

int run_foreground(const ForegroundArgs& a) {
  prepare_output_file(a.out);  // before any work
  bench::ForegroundBenchConfig c;
  c.quick = a.quick;
  std::cerr << "bench foreground: one car over about a fifth of a 640x426 frame at several sample counts...\n";
  const json r = bench::run_foreground_bench(c);
  std::vector<bench::ChartPoint> pts;
  for (const auto& row : r["runs"]) {
    const std::string label = std::to_string(row["spp"].get<int>()) + " spp" + (row["denoise"].get<bool>() ? " smoothed" : "");
    pts.push_back({label, row["seconds"].get<double>(), row["psnr"].get<double>()});
    std::printf("%-16s %6.2f s  PSNR %5.1f dB\n", label.c_str(), row["seconds"].get<double>(), row["psnr"].get<double>());
  }
  write_report(a.out, r);
  fs::path png(a.out);
  png.replace_extension(".png");
  bench::write_scatter_png(png, {"Foreground path tracing: noise (PSNR vs 1024 spp) against time per frame", "seconds per frame",
                                 "PSNR [dB]", true},
                           pts);
  return exit_code::kOk;
}

struct LightArgs {
  std::vector<std::string> hdri;
  std::string out = "bench/results/light.json", save_views, scene;
  int headings = 8, width = render::light::kDefaultCropWidth, every = 5;
  bool force = false;
};

int run_light(const LightArgs& a) {
  // Where the results go, checked before any work.
  prepare_output_file(a.out);
  std::optional<StagedOutputDir> views;
  if (!a.save_views.empty()) views.emplace(a.save_views, "images", a.force, "--save-views");
  json report = render::light::evaluate_panoramas(a.hdri, a.headings, a.width, views ? views->path().string() : "",
                                                  [](const std::string& line) { std::printf("%s\n", line.c_str()); });
  if (views) views->commit();
  std::vector<bench::ChartPoint> pts;
  for (const auto& r : report["panoramas"]) pts.push_back({r["panorama"], r["median_seconds"], r["median_angular_error_deg"]});
  // All panoramas' headings in two groups: the sun inside a crop, or out of them.
  for (const auto& [key, label] : {std::pair{"sun_in_view", "all: sun in a crop"}, {"sun_out_of_view", "all: sun out of the crops"}})
    if (report[key]["headings"].get<int>() > 0) pts.push_back({label, report[key]["median_seconds"], report[key]["median_angular_error_deg"]});
  if (!a.scene.empty()) {
    // A scene with vehicles and their shadows, which the panoramas do not have.
    const auto s = scene::load_scene(a.scene);
    const json r = render::light::evaluate_on_scene(s, a.every, [](const std::string& line) { std::cerr << "light: " << line << std::endl; });
    report["scene"] = r;
    pts.push_back({"scene: 1 frame", r["median_seconds"], r["median_angular_error_deg"]});
    pts.push_back({"scene: clip", r["clip"]["seconds"], r["clip"]["peak_angular_error_deg"]});
    std::printf("%-16s median sun error %6.1f deg, log10 intensity error %.2f (its own cameras and shadows, one frame)\n", s.name.c_str(),
                r["median_angular_error_deg"].get<double>(), r["median_log10_intensity_error"].get<double>());
    std::printf("%-16s sun error %6.1f deg, log10 intensity error %.2f (from %zu frames of the clip, as the agents estimate)\n", s.name.c_str(),
                r["clip"]["peak_angular_error_deg"].get<double>(), r["clip"]["log10_intensity_error"].get<double>(), r["clip"]["frames"].size());
  }
  write_report(a.out, report);
  fs::path png(a.out);
  png.replace_extension(".png");
  bench::write_scatter_png(png, {"Lighting estimation: median sun direction error per panorama (and demo scene: per frame, and the clip's as the agents)", "seconds per estimate",
                                 "median peak error [deg] (lower is better)", true},
                           pts);
  if (!a.hdri.empty()) {
    // null where nothing was measured (e.g. every panorama's sun clipped): printed as nan.
    const auto num = [](const json& j) { return j.is_number() ? j.get<double>() : NAN; };
    std::printf("all: median peak error %.1f deg (fixed-guess baseline %.1f deg), median log10 intensity error %.2f (%.2f with the clipped suns)\n",
                num(report["median_angular_error_deg"]), num(report["baseline_fixed_guess_median_angular_error_deg"]),
                num(report["median_log10_intensity_error"]), num(report["median_log10_intensity_error_with_clipped"]));
    for (const char* key : {"sun_in_view", "sun_out_of_view"})
      std::printf("%s: %d headings, median peak error %.1f deg\n", key, report[key]["headings"].get<int>(), num(report[key]["median_angular_error_deg"]));
  }
  return exit_code::kOk;
}

struct DeletionArgs {
  std::string scene, out = "bench/results/deletion.json", save, pair_scene, pair_model, model;
  int max_objects = 6;
  bool force = false;
};

int run_deletion(const DeletionArgs& a) {
  // Where the results go, checked before any work.
  prepare_output_file(a.out);
  std::optional<StagedOutputDir> staged;
  if (!a.save.empty()) staged.emplace(a.save, "images", a.force, "--save");
  const std::string save = staged ? staged->path().string() : "";
  const auto s = scene::load_scene(a.scene);
  // The pair scene is loaded first: a bad one fails now, not after the demo's measurements.
  std::optional<scene::Scene> ps;
  if (!a.pair_scene.empty()) ps = scene::load_scene(a.pair_scene);
  render::inpaint::DeletionEvalOptions o;
  o.progress = [](const std::string& line) { std::cerr << "deletion: " << line << std::endl; };
  o.max_objects = a.max_objects;
  o.save_dir = save;
  json r = render::inpaint::evaluate_deletion(s, o);
  if (!a.model.empty()) {
    // What the deletion agent does: the radiance field fills what the ground map cannot.
    const auto model = std::make_shared<render::gs::RadianceField>(render::gs::RadianceField::load(a.model));
    o.background = render::inpaint::field_renderer(model, s);
    o.save_dir = save.empty() ? "" : save + "/with-field";
    o.baseline = false;  // measured once above, on the same masks
    r["with_field"] = render::inpaint::evaluate_deletion(s, o)["summary"];
    // And in the views the field renders (a moved view), against the shifted truth views.
    r["moved_views"] = render::inpaint::evaluate_moved_view_deletion(s, model, save.empty() ? "" : save + "/moved-views")["summary"];
  }
  if (staged) staged->commit();
  if (ps) {
    // A real capture has no clean plates: a before / after pair beside the report instead.
    fs::path prefix(a.out);
    prefix.replace_extension("");
    std::shared_ptr<const render::gs::RadianceField> pair_field;
    if (!a.pair_model.empty()) pair_field = std::make_shared<render::gs::RadianceField>(render::gs::RadianceField::load(a.pair_model));
    r["before_after"] = render::inpaint::deletion_before_after(*ps, prefix.string() + "-" + ps->name + "-", pair_field);
    std::printf("before/after pair on %s: %s\n", ps->name.c_str(), r["before_after"]["images"].dump().c_str());
  }
  write_report(a.out, r);
  fs::path png(a.out);
  png.replace_extension(".png");
  const auto& sm = r["summary"];
  std::vector<bench::ChartPoint> pts{{"ground map + exemplar", sm["seconds_per_image"], sm["psnr"]},
                                     {"cv::inpaint Telea", sm["baseline_seconds_per_image"], sm["baseline_psnr"]}};
  if (r.contains("with_field")) {
    const auto& f = r["with_field"];
    pts.push_back({"ground map + radiance field (the agent)", f["seconds_per_image"], f["psnr"]});
    std::printf("deletion with the radiance field behind: PSNR %.2f dB, SSIM %.3f, %.2f s per image, flicker %.2f\n", f["psnr"].get<double>(),
                f["ssim"].get<double>(), f["seconds_per_image"].get<double>(), f["flicker"].get<double>());
  }
  bench::write_scatter_png(png, {"Deletion inside the mask vs clean plates", "seconds per image", "PSNR in the mask [dB]", true}, pts);
  if (r.contains("moved_views") && r["moved_views"].contains("psnr_agent")) {
    const auto& m = r["moved_views"];
    fs::path moved_png(a.out);
    moved_png.replace_filename(moved_png.stem().string() + "-moved-views.png");
    bench::write_scatter_png(moved_png,
                             {"Deletion in moved views vs shifted truth (where a fill changed the render)", "seconds per image",
                              "PSNR [dB]", false},
                             {{"the field's render, nothing removed", 0.0, m["psnr_field"]},
                              {"outlines only", m["seconds_per_image_outline_only"], m["psnr_outline_only"]},
                              {"+ whole paths", m["seconds_per_image_path_ungated"], m["psnr_path_ungated"]},
                              {"+ paths where they differ (the agent)", m["seconds_per_image_agent"], m["psnr_agent"]}});
    std::printf("deletion in moved views (%d views, %ld pixels): field %.2f dB, outlines only %.2f, whole paths %.2f, the agent %.2f\n",
                m["scored_views"].get<int>(), m["scored_pixels"].get<long>(), m["psnr_field"].get<double>(),
                m["psnr_outline_only"].get<double>(), m["psnr_path_ungated"].get<double>(), m["psnr_agent"].get<double>());
  }
  std::printf("deletion: PSNR %.2f dB (Telea %.2f dB), %.2f s per image (Telea %.2f s), flicker %.2f (Telea %.2f)\n",
              sm["psnr"].get<double>(), sm["baseline_psnr"].get<double>(), sm["seconds_per_image"].get<double>(),
              sm["baseline_seconds_per_image"].get<double>(), sm["flicker"].get<double>(), sm["baseline_flicker"].get<double>());
  return exit_code::kOk;
}

// PSNR against training and render time, on the demo's noise-free ground-truth views where the
// scene has them, else on the held-out images (the title says which).
void chart_nvs(const json& report, const fs::path& out) {
  std::vector<bench::ChartPoint> train_pts, render_pts;
  std::string set = "held_out";
  for (const auto& run : report["runs"])
    if (run["sets"].contains("truth_unshifted")) set = "truth_unshifted";
  for (const auto& run : report["runs"]) {
    if (!run["sets"].contains(set)) continue;
    const auto& v = run["sets"][set];
    train_pts.push_back({run["config"], run["train_seconds"].get<double>() / 60, v["psnr"]});
    render_pts.push_back({run["config"], v["render_s"], v["psnr"]});
  }
  const std::string what = set == "held_out" ? "held-out images" : "ground-truth views";
  const std::string scene = report["scene"];
  fs::path png(out);
  png.replace_extension("");
  bench::write_scatter_png(png.string() + "-train.png", {"Radiance field on " + scene + ": PSNR on " + what + " against training time",
                                                         "training [min]", "PSNR [dB]", false}, train_pts);
  bench::write_scatter_png(png.string() + "-render.png", {"Radiance field on " + scene + ": PSNR on " + what + " against render time",
                                                          "seconds per image", "PSNR [dB]", false}, render_pts);
}

struct NvsArgs {
  std::string scene, out;
  std::vector<std::string> configs{"fast-500", "fast-1000", "fast", "fast-no-exposure", "fast-no-pose-refinement"};
  int holdout = 8, max_width = 0;
  std::string redraw;
};

int run_nvs(const NvsArgs& a) {
  if (!a.redraw.empty()) {
    // Charts again from an earlier report, without training.
    std::ifstream in(a.redraw);
    if (!in) {
      std::cerr << a.redraw << ": cannot read the report\n";
      return exit_code::kUsage;
    }
    chart_nvs(json::parse(in), a.redraw);
    return exit_code::kOk;
  }
  if (a.scene.empty()) {
    std::cerr << "bench nvs: --scene is required (or --redraw REPORT)\n";
    return exit_code::kUsage;
  }
  // Every name is checked before the first one trains (a typo would otherwise end a long run).
  std::vector<render::gs::TrainOptions> options;
  for (const auto& name : a.configs) {
    render::gs::TrainOptions base;
    base.holdout = a.holdout;
    base.max_width = a.max_width;
    try {
      options.push_back(render::gs::parse_train_config_name(name, base));
    } catch (const std::invalid_argument& e) {
      std::cerr << "bench nvs: --configs: " << e.what() << "\n";
      return exit_code::kUsage;
    }
  }
  const auto s = scene::load_scene(a.scene);
  const std::string out = a.out.empty() ? "bench/results/nvs-" + s.name + ".json" : a.out;
  prepare_output_file(out);  // before the first training
  json runs = json::array(), ceiling;
  for (size_t k = 0; k < a.configs.size(); ++k) {
    const std::string& name = a.configs[k];
    render::gs::TrainOptions o = options[k];
    std::cerr << "bench nvs: " << name << "...\n";
    ProgressBar bar("train " + name);
    o.progress = train_progress(bar, o.coarse_share);
    render::gs::TrainReport tr;
    const auto model = render::gs::train(s, o, &tr);
    bar.finish();
    render::gs::NvsOptions no;
    no.holdout = a.holdout;
    const json ev = render::gs::evaluate_nvs(model, s, no);
    if (ev.contains("held_out_ceiling")) ceiling = ev["held_out_ceiling"];  // the same for every model
    runs.push_back({{"config", name}, {"train_seconds", tr.seconds}, {"iterations", tr.iterations}, {"converged", tr.converged},
                    {"gaussians", tr.gaussians}, {"train_psnr", tr.train_psnr}, {"sets", ev["sets"]}, {"width", ev["width"]}});
    if (ev.contains("pose_error")) runs.back()["pose_error"] = ev["pose_error"];
    for (const auto& [k, v] : ev["sets"].items())
      std::printf("  %-24s %-26s PSNR %5.2f dB  SSIM %.3f  %.3f s/image\n", name.c_str(), k.c_str(), v["psnr"].get<double>(),
                  v["ssim"].get<double>(), v["render_s"].get<double>());
    std::printf("  %-24s trained %.0f s, %d iterations, %zu Gaussians\n", name.c_str(), tr.seconds, tr.iterations, tr.gaussians);
  }
  json report{{"scene", s.name}, {"holdout", a.holdout}, {"runs", runs},
              {"targets", {{"demo_fast_train_minutes", 10}, {"demo_psnr_db", 30}, {"demo_ssim", 0.9},
                           {"nuscenes_psnr_db", 24}, {"render_seconds_640x426", 1}}}};
  if (!ceiling.is_null()) {
    report["held_out_ceiling"] = ceiling;
    std::printf("  held-out images against their noise-free views (a perfect model): PSNR %5.2f dB  SSIM %.3f\n",
                ceiling["psnr"].get<double>(), ceiling["ssim"].get<double>());
  }
  write_report(out, report);
  chart_nvs(report, out);
  return exit_code::kOk;
}

}  // namespace

void add_render_bench_commands(CLI::App& bench, int& result) {
  auto na = std::make_shared<NvsArgs>();
  auto* nvs = bench.add_subcommand("nvs", "Radiance field: train several sizes and the ablations (no exposure, no pose "
                                          "refinement), evaluate each on held-out and ground-truth views; PSNR against "
                                          "training and render time (long: minutes per configuration)");
  nvs->add_option("--scene", na->scene, "scene directory");
  nvs->add_option("--redraw", na->redraw, "only draw the charts again from this report (no training)")->check(CLI::ExistingFile);
  nvs->add_option("--out", na->out, "JSON report (replaced; default bench/results/nvs-<scene>.json; PNG charts beside it)");
  nvs->add_option("--configs", na->configs, "configurations: <preset>[-<iterations>][-no-exposure][-no-pose-refinement][-dssim][-coarse] (-dssim: 0.2 D-SSIM in the loss; -coarse: " +
                      std::to_string(std::lround(100 * render::gs::kCoarseConfigShare)) + " % of the iterations at half resolution)");
  nvs->add_option("--holdout", na->holdout, "hold out frames with index % N == N/2");
  nvs->add_option("--max-width", na->max_width, "downscale wider images to this width");
  nvs->callback([na, &result] { result = run_nvs(*na); });
  auto fa = std::make_shared<ForegroundArgs>();
  auto* fg = bench.add_subcommand("foreground", "Path tracing a car: noise against time per frame at several sample counts");
  fg->add_option("--out", fa->out, "JSON report (replaced; a PNG chart beside it)")->capture_default_str();
  fg->add_flag("--quick", fa->quick, "a 256-sample reference instead of 1024");
  fg->callback([fa, &result] { result = run_foreground(*fa); });
  auto la = std::make_shared<LightArgs>();
  auto* light = bench.add_subcommand("light", "Lighting estimation on HDR panoramas (e.g. blender-data's outdoor EXRs), "
                                              "against a fixed-guess baseline");
  light->add_option("--hdri", la->hdri, "panoramas")->required()->check(CLI::ExistingFile);
  light->add_option("--headings", la->headings, "headings per panorama");
  light->add_option("--width", la->width, "crop width");
  light->add_option("--out", la->out, "JSON report (replaced; a PNG chart beside it)")->capture_default_str();
  light->add_option("--save-views", la->save_views, "write the LDR crops the estimator saw to this folder (new, empty, or "
                                                    "images chatsim wrote)");
  light->add_flag("--force", la->force, kForceHelp);
  light->add_option("--scene", la->scene, "also a demo scene, against its ground-truth sky (ground_truth/sky.json)");
  light->add_option("--every", la->every, "with --scene: every N-th frame")->check(CLI::Range(1, 10000));
  light->callback([la, &result] { result = exit_code_of([&] { return run_light(*la); }); });
  auto da = std::make_shared<DeletionArgs>();
  auto* del = bench.add_subcommand("deletion", "Deletion against the demo scene's clean plates, against cv::inpaint Telea");
  del->add_option("--scene", da->scene, "a rendered demo scene")->required();
  del->add_option("--out", da->out, "JSON report (replaced; a PNG chart beside it)")->capture_default_str();
  del->add_option("--max-objects", da->max_objects, "vehicles to remove (largest plates first)");
  del->add_option("--save", da->save, "before / after / baseline / plate images into this folder (new, empty, or images "
                                      "chatsim wrote)");
  del->add_flag("--force", da->force, kForceHelp);
  del->add_option("--model", da->model,
                  "a radiance field of the scene (chatsim train, or the one chatsim run cached): also measure the fill the "
                  "deletion agent makes, with the field behind the vehicle")
      ->check(CLI::ExistingFile);
  del->add_option("--pair-scene", da->pair_scene,
                  "also remove a parked vehicle from this scene (e.g. the imported nuScenes scene) and save a "
                  "before / after / Telea image set beside the report")
      ->check(CLI::ExistingDirectory);
  del->add_option("--pair-model", da->pair_model,
                  "the pair scene's radiance field: also save the fill the deletion agent makes there, with the field "
                  "behind the vehicle (<out>-<scene>-after-field.png)")
      ->check(CLI::ExistingFile)
      ->needs("--pair-scene");
  del->callback([da, &result] { result = run_deletion(*da); });
}

}  // namespace chatsim::cli
