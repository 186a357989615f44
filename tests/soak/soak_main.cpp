// chatsim-soak: a long mixed sequence of commands through the whole process graph: mostly
// decisions only, plus a rendered subset (every --render-every'th command, a rendered round on a
// small rendered demo scene). Reports responses lost (must be 0), errors by kind, latency
// percentiles, and each process's resident memory after warm-up and at the end (growth must
// stay under 10 %).
//   chatsim-soak [--count 500] [--render-every 25] [--out bench/results/soak.json]
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/scene/demo_layout.hpp"
#include "common/util/clock.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/log.hpp"
#include "common/util/output_dir.hpp"
#include "render/demo/demo_generate.hpp"
#include "processes/cli/process_graph.hpp"

namespace fs = std::filesystem;
using namespace chatsim;
using nlohmann::json;

namespace {

long rss_kb(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

std::vector<std::string> commands(const fs::path& cases) {
  std::vector<std::string> out;
  std::ifstream in(cases);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const json c = json::parse(line);  // kept alive: a range-for over a temporary's member dangles
    for (const auto& r : c["rounds"]) out.push_back(r.get<std::string>());
  }
  return out;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(p * double(v.size() - 1) + 0.5))];
}

// A variable for the rendering agents this process starts, unless the user set it.
void default_env(const char* name, const std::string& value) { setenv(name, value.c_str(), 0); }

// The rendered subset's scene: the small demo (160 x 106, 8 frames), no ground truth.
fs::path render_small_scene(const fs::path& dir) {
  auto o = render::demo::small_demo_options(scene::DemoOptions{}.seed);
  o.clean_plates = false;
  o.truth_views = false;
  render::demo::generate_demo_scene(o, dir);
  return dir;
}

json latency_summary(const std::vector<double>& ms) {
  return {{"p50", percentile(ms, 0.5)}, {"p90", percentile(ms, 0.9)}, {"p99", percentile(ms, 0.99)}, {"max", percentile(ms, 1.0)}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("chatsim-soak: many commands (a rendered subset among them) through the process graph; loss, errors, "
               "latency, memory");
  int count = 500;
  int warmup = 200;  // > 64 conversations x 3 rounds: the manager's conversation cache is full by then
  int render_every = 25;
  // Rendering agents grow while their first rounds load models, assets and thread arenas (the
  // deletion agent: 128 to 197 MB over its first 10 rendered rounds, flat over the next 70).
  int render_warmup = 10;
  std::string out = "bench/results/soak.json";
  std::string cases = std::string(CHATSIM_SOURCE_DIR) + "/tests/data/commands-paraphrase.jsonl";
  app.add_option("--count", count, "commands to send")->check(CLI::Range(1, 1000000));
  app.add_option("--warmup", warmup, "commands before the first memory reading");
  app.add_option("--render-warmup", render_warmup, "rendered rounds before the first memory reading (at most all of them)");
  app.add_option("--cases", cases, "command cases to cycle through (JSON lines)");
  app.add_option("--render-every", render_every,
                 "every Nth command is a rendered round on a small rendered scene (0: decisions only)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--out", out, "JSON report (empty: do not write)");
  CLI11_PARSE(app, argc, argv);
  init_logging("soak");
  try {
    if (!out.empty()) prepare_output_file(out);  // before the long run, not after
  } catch (const OutputDirError& e) {
    std::cerr << "chatsim-soak: " << e.what() << "\n";
    return exit_code::kUsage;
  }

  const auto work = fs::temp_directory_path() / ("chatsim-soak-" + std::to_string(getpid()));
  const auto scene_dir = work / "layout";
  scene::save_scene(scene::demo_layout({}), scene_dir);
  const auto all = commands(cases);
  if (all.empty()) {
    std::cerr << "chatsim-soak: " << cases << " has no commands\n";
    fs::remove_all(work);
    return exit_code::kUsage;
  }
  std::vector<std::string> kinds = {"manager", "view", "deletion", "asset", "motion"};
  fs::path rendered_scene;
  if (render_every > 0 && render_every <= count) {
    std::cerr << "chatsim-soak: rendering the small scene for the rendered subset\n";
    rendered_scene = render_small_scene(work / "rendered");
    // A cache of its own (removed at the end): the first rendered round trains, the user's cache is left alone.
    setenv("CHATSIM_CACHE", (work / "cache").c_str(), 1);
    // Low cost per rendered round, unless the user asks for more.
    default_env("CHATSIM_TRAIN_ITERATIONS", "40");
    default_env("CHATSIM_FOREGROUND_SPP", "4");
    kinds.insert(kinds.end(), {"background", "foreground"});
  }
  cli::ProcessGraph graph("", kinds);  // private bus and agents, stopped at the end
  bus::NodeOptions o;
  o.name = "soak-" + std::to_string(getpid());
  o.kind = "cli";
  o.bus = graph.endpoint();
  o.heartbeat_period = std::chrono::milliseconds(0);
  bus::Node node(o);
  std::map<std::string, int> pids;
  node.subscribe(std::string(bus::topics::kHeartbeat), [&](const bus::Message& m) {
    if (const auto* hb = m.payload<msgs::Heartbeat>()) pids[std::string(bus::view(hb->node()))] = hb->pid();
  });
  node.start();
  for (const double until = mono_s() + 1.5; mono_s() < until;) node.spin_once(std::chrono::milliseconds(50));

  std::vector<double> latency_ms, rendered_ms;
  std::map<std::string, int> errors;
  std::map<std::string, long> rss_start, rss_end;
  int lost = 0, ok = 0, refused = 0, rendered = 0, rendered_ok = 0, outputs_missing = 0;
  const int rendered_total = rendered_scene.empty() ? 0 : count / render_every;
  int baseline_at = -1;  // the command before which memory was first read
  for (int i = 0; i < count; ++i) {
    if (baseline_at < 0 && i >= std::min(warmup, count - 1) && rendered >= std::min(render_warmup, rendered_total)) {
      baseline_at = i;
      for (const auto& k : kinds) rss_start[k] = pids.count(k) ? rss_kb(pids[k]) : -1;
    }
    const bool render = !rendered_scene.empty() && (i + 1) % render_every == 0;
    // Three rounds per conversation; a rendered round is a conversation of its own, on the rendered scene.
    const std::string conversation = render ? "soak-rendered-" + std::to_string(i) : "soak-" + std::to_string(i / 3);
    const std::string& command = all[size_t(i) % all.size()];
    const fs::path result_dir = work / ("round-" + std::to_string(i));
    flatbuffers::FlatBufferBuilder fbb;
    const auto req = msgs::CreateChatRequestDirect(fbb, conversation.c_str(), (render ? rendered_scene : scene_dir).c_str(),
                                                   command.c_str(), render, render ? result_dir.c_str() : "");
    const double t0 = mono_s();
    const auto r = node.call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(),
                             std::chrono::seconds(render ? 900 : 60));
    (render ? rendered_ms : latency_ms).push_back((mono_s() - t0) * 1000);
    rendered += render ? 1 : 0;
    if (!r.ok()) {
      ++lost;
      continue;
    }
    const auto* resp = r.response->payload<msgs::ChatResponse>();
    if (resp == nullptr || !resp->ok()) {
      errors[resp && resp->error() ? msgs::EnumNameErrorCode(resp->error()->code()) : "NoResponse"]++;
      outputs_missing += render ? 1 : 0;
      continue;
    }
    ++ok;
    const auto state = json::parse(bus::view(resp->edit_state_json()));
    refused += state["unresolved"].empty() ? 0 : 1;
    if (render) {
      // Answered is not enough: the result folder is whole (labels and video written).
      const bool whole = fs::exists(result_dir / "result.json") && fs::exists(result_dir / "video.mp4");
      rendered_ok += whole ? 1 : 0;
      outputs_missing += whole ? 0 : 1;
      fs::remove_all(result_dir);
      std::cerr << "  rendered round " << rendered << " (command " << i + 1 << "): " << int(rendered_ms.back()) << " ms\n";
    }
    if ((i + 1) % 50 == 0) std::cerr << "  " << i + 1 << "/" << count << " commands\n";
  }
  node.spin_once(std::chrono::milliseconds(100));
  json memory = json::object();
  double worst_growth = 0;
  for (const auto& k : kinds) {
    rss_end[k] = pids.count(k) ? rss_kb(pids[k]) : -1;
    const double growth = rss_start[k] > 0 ? double(rss_end[k] - rss_start[k]) / double(rss_start[k]) : 0.0;
    worst_growth = std::max(worst_growth, growth);
    memory[k] = {{"rss_kb_after_warmup", rss_start[k]}, {"rss_kb_end", rss_end[k]}, {"growth", growth}};
  }
  node.shutdown();
  fs::remove_all(work);
  const json report{{"commands", count},
                    {"answered_ok", ok},
                    {"with_unresolved", refused},
                    {"responses_lost", lost},
                    {"errors_by_kind", errors},
                    {"latency_ms", latency_summary(latency_ms)},
                    {"rendered", {{"rounds", rendered}, {"whole_results", rendered_ok}, {"results_missing", outputs_missing},
                                  {"scene", "small demo, 160x106, 8 frames, 3 cameras"}, {"latency_ms", latency_summary(rendered_ms)}}},
                    {"memory", memory},
                    {"memory_first_read_before_command", baseline_at + 1},
                    {"worst_rss_growth", worst_growth},
                    {"passed", lost == 0 && outputs_missing == 0 && worst_growth < 0.10}};
  std::cout << report.dump(1) << std::endl;
  if (!out.empty()) std::ofstream(out) << report.dump(1) << "\n";
  return report["passed"].get<bool>() ? exit_code::kOk : exit_code::kFailure;
}
