// chatsim bench e2e: the paper's kind of command through every agent process, timed by stage.
// For the first preset, four runs: the first (training the scene's model when it is not cached
// yet), the same command again with the model cached but every rendering stage computed (the
// target: under 2 minutes), the same command once more in a new conversation (everything
// reused), and a follow-up round that changes one added vehicle (only the foreground is
// rendered again). Every other preset: the first two. For every preset, when the scene has
// clean plates: a removal command's result against them, charted against the command's time.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "agents/render/render_cache.hpp"
#include "bench/chart.hpp"
#include "bench/plate_accuracy.hpp"
#include "agents/render/render_pipeline.hpp"
#include "common/scene/scene.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "processes/cli/chat_session.hpp"
#include "processes/cli/commands.hpp"
#include "common/util/preset_names.hpp"

namespace chatsim::cli {
void write_report(const std::filesystem::path& file, const nlohmann::json& report);

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

struct E2eArgs {
  std::string scene, out = "bench/results/e2e.json", work;
  std::string command =
      "Remove all cars, add a police car chasing a Porsche that drives the wrong way toward me, and move the view 5 m ahead";
  std::string follow_up = "Now make the Porsche yellow and faster.";
  std::string removal = "Remove all cars.";
  std::vector<std::string> presets = {"fast", "draft"};
  double timeout_s = 6 * 3600;
};

json read_result(const std::string& dir) {
  std::ifstream in(fs::path(dir) / "result.json");
  if (!in) throw std::runtime_error(dir + "/result.json is missing: the round produced no result");
  return json::parse(in);
}

int run_e2e(const E2eArgs& a) {
  const std::string scene_dir = fs::absolute(a.scene).lexically_normal().string();
  const auto s = scene::load_scene(scene_dir);
  if (s.layout_only) {
    std::cerr << scene_dir << " is a layout-only scene: render the demo scene without --layout-only\n";
    return exit_code::kUsage;
  }
  const bool has_plates = fs::exists(s.dir / "ground_truth" / "clean_plates.json");
  // Where the results go, checked before any work.
  prepare_output_file(a.out);
  const fs::path work = prepare_rounds_root(
      a.work.empty() ? (fs::temp_directory_path() / ("chatsim-bench-e2e-" + std::to_string(::getpid()))).string() : a.work,
      scene_dir, false, "--work");
  const fs::path renders = agents::render::cache_root() / "renders" / agents::render::scene_key(s);
  json runs = json::array(), presets = json::array();
  std::vector<bench::StackedBar> bars;
  std::vector<bench::ChartPoint> points;
  int step = 0;
  const int steps = 4 + 2 * int(a.presets.size() - 1) + (has_plates ? int(a.presets.size()) : 0);
  auto one = [&](const std::string& label, ChatSession& session, const std::string& command, const std::string& preset) {
    std::cerr << "bench e2e: " << ++step << "/" << steps << " " << label << "\n";
    const auto t0 = std::chrono::steady_clock::now();
    const std::string dir = (work / (preset + "-" + std::to_string(step))).string();
    const auto r = session.round(command, dir, a.timeout_s, preset);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r.ok) throw std::runtime_error(label + ": " + r.message);
    json res = read_result(r.output_dir);
    runs.push_back({{"run", label}, {"preset", preset}, {"wall_seconds", wall}, {"seconds", res["seconds"]},
                    {"reused", res["reused"]}, {"images", res["images"]}});
    bench::StackedBar bar{label, {}};
    double staged = 0;
    for (const char* stage : {"training", "background", "deletion", "foreground", "composition_and_encoding"})
      if (res["seconds"].contains(stage)) {
        bar.segments.emplace_back(stage, res["seconds"][stage].get<double>());
        staged += res["seconds"][stage].get<double>();
      }
    bar.segments.emplace_back("decisions and messaging", std::max(0.0, wall - staged));
    bars.push_back(bar);
    std::printf("%-44s %7.1f s wall  (%s)\n", label.c_str(), wall, res["seconds"].dump().c_str());
    res["wall_seconds"] = wall;
    res["output_dir"] = r.output_dir;
    res["removed"] = r.edit_state.value("removed", json::array());
    return res;
  };
  try {
    for (size_t i = 0; i < a.presets.size(); ++i) {
      const std::string& p = a.presets[i];
      json entry{{"preset", p}, {"foreground_spp", agents::render::render_preset(p).foreground_spp}};
      {
        ChatSession session("", scene_dir, "");
        const json first = one(p + ": first run (model trained if needed)", session, a.command, p);
        entry["training_seconds"] = first["seconds"].value("training", 0.0);
      }
      fs::remove_all(renders);  // keep the models, drop the rendered stages
      {
        ChatSession session("", scene_dir, "");
        const json cached = one(p + ": model cached, stages rendered", session, a.command, p);
        entry["model_cached_seconds"] = cached["wall_seconds"];
        if (i == 0) {
          // A new conversation: the same command is the same edit (in the old one it would
          // move the view further and add more vehicles).
          ChatSession again("", scene_dir, "");
          one(p + ": same command again", again, a.command, p);
          one(p + ": follow-up round", again, a.follow_up, p);
        }
      }
      if (has_plates) {
        // Accuracy: removing the vehicles in the captured view, against the clean plates.
        ChatSession session("", scene_dir, "");
        const json rem = one(p + ": '" + a.removal + "' against clean plates", session, a.removal, p);
        const auto acc = bench::plate_accuracy(s, rem["output_dir"].get<std::string>(), rem["removed"].get<std::vector<std::string>>());
        entry["removal"] = bench::to_json(acc);
        entry["removal"]["seconds"] = rem["wall_seconds"];
        points.push_back({p + " (" + std::to_string(entry["foreground_spp"].get<int>()) + " spp)",
                          entry["model_cached_seconds"].get<double>(), acc.psnr_db});
        std::printf("%s: removal PSNR %.2f dB against the clean plates (%d plates; the captured image: %.2f dB)\n", p.c_str(),
                    acc.psnr_db, acc.plates, acc.captured_psnr_db);
      }
      presets.push_back(entry);
    }
  } catch (const std::exception& e) {
    std::cerr << "bench e2e: " << e.what() << "\n";
    if (a.work.empty()) fs::remove_all(work);
    return exit_code::kFailure;
  }
  if (a.work.empty()) fs::remove_all(work);
  // Each run's wall time against the first preset's fully rendered one: what reuse saves.
  json ratios = json::object();
  if (runs.size() > 1)
    for (const auto& r : runs) ratios[r["run"].get<std::string>()] = r["wall_seconds"].get<double>() / runs[1]["wall_seconds"].get<double>();
  const json report{{"scene", s.name}, {"command", a.command}, {"follow_up", a.follow_up}, {"removal", a.removal},
                    {"images", runs.empty() ? json() : runs[0]["images"]}, {"runs", runs}, {"presets", presets},
                    {"baseline", "the first preset's run of the same command with the model cached and every stage rendered, in the same benchmark"},
                    {"ratio_to_baseline", ratios},
                    {"accuracy", has_plates ? "PSNR (8-bit sRGB) of the result of the removal command against the scene's clean "
                                              "plates, over the pixels the removed vehicles changed"
                                            : "not measured: the scene has no clean plates"},
                    {"targets", {{"model_cached_seconds", 120}}}};
  write_report(a.out, report);
  fs::path png(a.out);
  png.replace_extension(".png");
  bench::write_stacked_bars_png(png, "End to end on " + s.name + ": seconds by stage", "seconds", bars);
  if (!points.empty()) {
    fs::path chart(a.out);
    chart.replace_filename(chart.stem().string() + "-presets.png");
    bench::write_scatter_png(chart, {"Pipeline by preset on " + s.name + ": removal accuracy vs the command's time",
                                     "seconds for the paper's command, model cached", "PSNR vs clean plates [dB]", false},
                             points);
  }
  return exit_code::kOk;
}

}  // namespace

void add_e2e_bench_command(CLI::App& bench, int& result) {
  auto a = std::make_shared<E2eArgs>();
  auto* e2e = bench.add_subcommand("e2e", "The paper's kind of command through every agent process, timed by stage: first run, "
                                          "model cached, everything reused, a follow-up round (starts the processes itself)");
  e2e->add_option("--scene", a->scene, "a rendered scene (e.g. the demo scene)")->required();
  e2e->add_option("--out", a->out, "JSON report (a PNG chart beside it)");
  e2e->add_option("--command", a->command, "the command");
  e2e->add_option("--follow-up", a->follow_up, "the follow-up round");
  e2e->add_option("--removal", a->removal, "the command whose result is compared with the clean plates");
  e2e->add_option("--presets", a->presets, "rendering presets, the first one the baseline")
      ->delimiter(',')
      ->check(CLI::IsMember(preset_names()));
  e2e->add_option("--work", a->work, "keep the results in this folder: new, empty, or one chatsim made for results "
                                    "(default: a temporary one, removed after)");
  e2e->add_option("--timeout-s", a->timeout_s, "how long to wait for each round")->check(CLI::PositiveNumber);
  e2e->callback([a, &result] { result = run_e2e(*a); });
}

}  // namespace chatsim::cli
