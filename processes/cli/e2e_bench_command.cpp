// chatsim bench e2e: the paper's kind of command through every agent process, timed by stage.
// Four runs in one: the first (training the scene's model when it is not cached yet), the
// same command again with the model cached but every rendering stage computed (the target:
// under 2 minutes), the same command once more in a new conversation (everything reused), and
// a follow-up round that changes one added vehicle (only the foreground is rendered again).
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "agents/render/render_cache.hpp"
#include "bench/chart.hpp"
#include "common/scene/scene.hpp"
#include "common/util/exit_codes.hpp"
#include "processes/cli/chat_session.hpp"
#include "processes/cli/commands.hpp"

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
  const fs::path work = a.work.empty() ? fs::temp_directory_path() / ("chatsim-bench-e2e-" + std::to_string(::getpid())) : fs::path(a.work);
  const fs::path renders = agents::render::cache_root() / "renders" / agents::render::scene_key(s);
  json runs = json::array();
  std::vector<bench::StackedBar> bars;
  auto one = [&](const std::string& label, ChatSession& session, const std::string& command, bool render) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = session.round(command, render ? (work / label).string() : "", a.timeout_s);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r.ok) throw std::runtime_error(label + ": " + r.message);
    if (!render) return;
    const json res = read_result(r.output_dir);
    runs.push_back({{"run", label}, {"wall_seconds", wall}, {"seconds", res["seconds"]}, {"reused", res["reused"]},
                    {"images", res["images"]}});
    bench::StackedBar bar{label, {}};
    double staged = 0;
    for (const char* stage : {"training", "background", "deletion", "foreground", "composition_and_encoding"})
      if (res["seconds"].contains(stage)) {
        bar.segments.emplace_back(stage, res["seconds"][stage].get<double>());
        staged += res["seconds"][stage].get<double>();
      }
    bar.segments.emplace_back("decisions and messaging", std::max(0.0, wall - staged));
    bars.push_back(bar);
    std::printf("%-34s %7.1f s wall  (%s)\n", label.c_str(), wall, res["seconds"].dump().c_str());
  };
  try {
    {
      ChatSession session("", scene_dir, "");
      std::cerr << "bench e2e: 1/4 first run (trains the scene's model if it is not cached)\n";
      one("first (model trained if needed)", session, a.command, true);
    }
    fs::remove_all(renders);  // keep the model, drop the rendered stages
    {
      ChatSession session("", scene_dir, "");
      std::cerr << "bench e2e: 2/4 model cached, every stage rendered\n";
      one("model cached, stages rendered", session, a.command, true);
    }
    {
      // A new conversation: the same command is the same edit (in the old one it would move
      // the view further and add more vehicles).
      ChatSession session("", scene_dir, "");
      std::cerr << "bench e2e: 3/4 the same command in a new conversation (everything reused)\n";
      one("same command again", session, a.command, true);
      std::cerr << "bench e2e: 4/4 a follow-up round\n";
      one("follow-up round", session, a.follow_up, true);
    }
  } catch (const std::exception& e) {
    std::cerr << "bench e2e: " << e.what() << "\n";
    return exit_code::kFailure;
  }
  if (a.work.empty()) fs::remove_all(work);
  // Each run's wall time against the fully rendered one: what reuse saves.
  json ratios = json::object();
  if (runs.size() > 1)
    for (const auto& r : runs) ratios[r["run"].get<std::string>()] = r["wall_seconds"].get<double>() / runs[1]["wall_seconds"].get<double>();
  const json report{{"scene", s.name}, {"command", a.command}, {"follow_up", a.follow_up},
                    {"images", runs.empty() ? json() : runs[0]["images"]}, {"runs", runs},
                    {"baseline", "the same command with the model cached and every stage rendered, in the same benchmark"},
                    {"ratio_to_baseline", ratios},
                    {"targets", {{"model_cached_seconds", 120}}}};
  write_report(a.out, report);
  fs::path png(a.out);
  png.replace_extension(".png");
  bench::write_stacked_bars_png(png, "End to end on " + s.name + ": seconds by stage", "seconds", bars);
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
  e2e->add_option("--work", a->work, "keep the results in this folder (default: a temporary one, removed after)");
  e2e->add_option("--timeout-s", a->timeout_s, "how long to wait for each round")->check(CLI::PositiveNumber);
  e2e->callback([a, &result] { result = run_e2e(*a); });
}

}  // namespace chatsim::cli
