// chatsim-soak: a long mixed sequence of commands through the whole decision process graph.
// Reports responses lost (must be 0), errors by kind, latency percentiles, and each process's
// resident memory after warm-up and at the end (growth must stay under 10 %).
//   chatsim-soak [--count 500] [--out bench/results/soak.json]
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("chatsim-soak: many commands through the decision process graph; loss, errors, latency, memory");
  int count = 500;
  int warmup = 200;  // > 64 conversations x 3 rounds: the manager's conversation cache is full by then
  std::string out = "bench/results/soak.json";
  std::string cases = std::string(CHATSIM_SOURCE_DIR) + "/tests/data/commands-paraphrase.jsonl";
  app.add_option("--count", count, "commands to send")->check(CLI::Range(1, 1000000));
  app.add_option("--warmup", warmup, "commands before the first memory reading");
  app.add_option("--cases", cases, "command cases to cycle through (JSON lines)");
  app.add_option("--out", out, "JSON report (empty: do not write)");
  CLI11_PARSE(app, argc, argv);
  init_logging("soak");

  const auto scene_dir = fs::temp_directory_path() / ("chatsim-soak-" + std::to_string(getpid()));
  scene::save_scene(scene::demo_layout({}), scene_dir);
  const auto all = commands(cases);
  if (all.empty()) {
    std::cerr << "chatsim-soak: " << cases << " has no commands\n";
    return exit_code::kUsage;
  }
  const std::vector<std::string> kinds = {"manager", "view", "deletion", "asset", "motion"};
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

  std::vector<double> latency_ms;
  std::map<std::string, int> errors;
  std::map<std::string, long> rss_start, rss_end;
  int lost = 0, ok = 0, refused = 0;
  for (int i = 0; i < count; ++i) {
    if (i == std::min(warmup, count - 1))
      for (const auto& k : kinds) rss_start[k] = pids.count(k) ? rss_kb(pids[k]) : -1;
    const std::string conversation = "soak-" + std::to_string(i / 3);  // three rounds per conversation
    const std::string& command = all[size_t(i) % all.size()];
    flatbuffers::FlatBufferBuilder fbb;
    const auto req = msgs::CreateChatRequestDirect(fbb, conversation.c_str(), scene_dir.c_str(), command.c_str());
    const double t0 = mono_s();
    const auto r = node.call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(), std::chrono::seconds(60));
    latency_ms.push_back((mono_s() - t0) * 1000);
    if (!r.ok()) {
      ++lost;
      continue;
    }
    const auto* resp = r.response->payload<msgs::ChatResponse>();
    if (resp == nullptr || !resp->ok()) {
      errors[resp && resp->error() ? msgs::EnumNameErrorCode(resp->error()->code()) : "NoResponse"]++;
      continue;
    }
    ++ok;
    const auto state = json::parse(bus::view(resp->edit_state_json()));
    refused += state["unresolved"].empty() ? 0 : 1;
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
  fs::remove_all(scene_dir);
  const json report{{"commands", count},
                    {"answered_ok", ok},
                    {"with_unresolved", refused},
                    {"responses_lost", lost},
                    {"errors_by_kind", errors},
                    {"latency_ms", {{"p50", percentile(latency_ms, 0.5)}, {"p90", percentile(latency_ms, 0.9)},
                                    {"p99", percentile(latency_ms, 0.99)}, {"max", percentile(latency_ms, 1.0)}}},
                    {"memory", memory},
                    {"worst_rss_growth", worst_growth},
                    {"passed", lost == 0 && worst_growth < 0.10}};
  std::cout << report.dump(1) << std::endl;
  if (!out.empty()) {
    fs::create_directories(fs::absolute(out).parent_path());
    std::ofstream(out) << report.dump(1) << "\n";
  }
  return report["passed"].get<bool>() ? exit_code::kOk : exit_code::kFailure;
}
