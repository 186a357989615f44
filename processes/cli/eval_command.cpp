// chatsim eval commands: grade the decision pipeline on command cases (JSON lines).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include <spdlog/spdlog.h>

#include "agents/core/agent_registry.hpp"
#include "agents/manager/manager.hpp"
#include "bench/chart.hpp"
#include "bench/command_grader.hpp"
#include "common/scene/scene.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/output_dir.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

using nlohmann::json;

struct EvalArgs {
  std::string cases;
  std::string scene;
  std::string backend;
  std::string out;
  std::string chart;
  int repeat = 1;
  bool verbose = false;
};

struct Case {
  std::string id, category;
  std::vector<std::string> rounds;
  json expect;
  std::string scene;  // the case's own scene (optional 'scene' field, relative to the cases file), or --scene
};

std::vector<Case> load_cases(const std::string& file, const std::string& default_scene) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot open the cases file");
  std::vector<Case> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = file + ":" + std::to_string(n);
    json j;
    try {
      j = json::parse(line);
    } catch (const json::parse_error& e) {
      throw std::runtime_error(where + ": not valid JSON: " + e.what());
    }
    for (const char* field : {"id", "category", "rounds", "expect"})
      if (!j.contains(field)) throw std::runtime_error(where + ": missing field '" + field + "'");
    if (!j["rounds"].is_array() || j["rounds"].empty()) throw std::runtime_error(where + ": 'rounds' must be a non-empty list");
    std::string scene = default_scene;
    if (j.contains("scene")) {
      if (!j["scene"].is_string()) throw std::runtime_error(where + ": 'scene' must be a path (relative to the cases file)");
      scene = (std::filesystem::path(file).parent_path() / j["scene"].get<std::string>()).lexically_normal().string();
    }
    if (scene.empty())
      throw std::runtime_error(where + ": the case names no 'scene' and no --scene was given; pass --scene DIR");
    out.push_back({j["id"], j["category"], j["rounds"].get<std::vector<std::string>>(), j["expect"], scene});
  }
  return out;
}

// Tallies of one evaluation, per category and per scene.
struct Tally {
  std::map<std::string, std::pair<int, int>> by_category, by_scene;  // passed, total
  std::map<std::string, std::pair<double, int>> latency_by_category;  // total ms, rounds
  std::map<std::string, double> max_ms_by_category;
  json failures = json::array();
  json slow_rounds = json::array();  // rounds over #41's targets: 300 ms abstract, 50 ms otherwise
  double total_ms = 0;
  int rounds = 0, passed = 0;
  bench::MotionQuality motion;
};

// Times each round of a case: the median of `repeat` runs of the whole conversation (a single
// round here varies up to 2x from run to run). The state is the last run's; decisions are
// deterministic, so every run gives the same one.
std::vector<double> time_rounds(agents::manager::Manager& manager, const Case& c, int repeat, json& state,
                                std::string& error_text) {
  std::vector<std::vector<double>> ms_of(c.rounds.size());
  for (int rep = 0; rep < repeat && error_text.empty(); ++rep) {
    for (size_t i = 0; i < c.rounds.size() && error_text.empty(); ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      try {
        state = manager.chat(c.id, c.scene, c.rounds[i]).edit_state;
      } catch (const std::exception& e) {
        error_text = std::string("round failed: ") + e.what();
      }
      ms_of[i].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    manager.reset(c.id);
  }
  std::vector<double> out;
  for (auto& v : ms_of) {
    if (v.empty()) break;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    out.push_back(v[v.size() / 2]);
  }
  return out;
}

// Sends one case's rounds through the manager and grades the final edit state.
void run_case(agents::manager::Manager& manager, const scene::Scene& scene, const Case& c, const EvalArgs& a,
              Tally& t) {
  json state;
  std::string error_text;
  const auto times = time_rounds(manager, c, a.repeat, state, error_text);
  for (size_t i = 0; i < times.size(); ++i) {
    const double ms = times[i];
    t.total_ms += ms;
    ++t.rounds;
    t.latency_by_category[c.category].first += ms;
    t.latency_by_category[c.category].second++;
    t.max_ms_by_category[c.category] = std::max(t.max_ms_by_category[c.category], ms);
    const double target = c.category == "abstract" ? 300 : 50;
    if (ms > target) t.slow_rounds.push_back({{"id", c.id}, {"round", i + 1}, {"ms", ms}, {"target_ms", target}});
  }
  const bool error = !error_text.empty();
  json case_fail = json::array();
  if (error) case_fail.push_back({{"check", "run"}, {"detail", error_text}});
  else
    for (const auto& r : bench::grade_case(scene, state, c.expect))
      if (!r.pass) case_fail.push_back({{"check", json::parse(r.check)}, {"detail", r.detail}});
  if (!error) {
    const auto q = bench::motion_quality(scene, state);
    t.motion.vehicles += q.vehicles;
    t.motion.on_lane += q.on_lane;
    t.motion.action_match += q.action_match;
    t.motion.speed_match += q.speed_match;
    t.motion.no_overlap += q.no_overlap;
    t.motion.clear_of_ego += q.clear_of_ego;
  }
  const bool ok = case_fail.empty();
  const json unresolved = state.is_object() ? state.value("unresolved", json::array()) : json::array();
  for (auto* tally : {&t.by_category[c.category], &t.by_scene[scene.name]}) {
    tally->second++;
    tally->first += ok;
  }
  t.passed += ok;
  if (!ok)  // what the system said it could not do explains most failures
    t.failures.push_back({{"id", c.id}, {"scene", scene.name}, {"rounds", c.rounds}, {"failed", case_fail},
                          {"unresolved", unresolved}});
  if (a.verbose)
    std::cerr << (ok ? "pass " : "FAIL ") << c.id
              << (ok ? "" : "  " + case_fail.dump() + "  unresolved: " + unresolved.dump()) << "\n";
}

double share(int k, int n) { return n ? double(k) / n : 1.0; }

json make_report(const EvalArgs& a, const std::string& backend, size_t cases, const std::vector<std::string>& scenes,
                 const Tally& t) {
  json cats = json::object(), by_scene = json::object();
  for (const auto& [name, pt] : t.by_category) {
    const auto& lat = t.latency_by_category.at(name);
    cats[name] = {{"passed", pt.first}, {"total", pt.second}, {"accuracy", double(pt.first) / pt.second},
                  {"mean_decision_latency_ms", lat.first / lat.second},
                  {"max_decision_latency_ms", t.max_ms_by_category.at(name)}};
  }
  for (const auto& [name, pt] : t.by_scene)
    by_scene[name] = {{"passed", pt.first}, {"total", pt.second}, {"accuracy", double(pt.first) / pt.second}};
  return json{{"cases_file", a.cases},
              {"scene", scenes.size() == 1 ? json(scenes.front()) : json(scenes)},
              {"backend", backend},
              {"cases", cases},
              {"passed", t.passed},
              {"accuracy", share(t.passed, int(cases))},
              {"by_category", cats},
              {"by_scene", by_scene},
              {"by_backend", {{backend, share(t.passed, int(cases))}}},
              {"mean_decision_latency_ms", t.rounds ? t.total_ms / t.rounds : 0.0},
              {"timed_by", a.repeat > 1 ? "median of " + std::to_string(a.repeat) + " runs per round" : "one run"},
              {"motion", {{"vehicles", t.motion.vehicles}, {"on_lane", share(t.motion.on_lane, t.motion.vehicles)},
                          {"action_match", share(t.motion.action_match, t.motion.vehicles)},
                          {"speed_match", share(t.motion.speed_match, t.motion.vehicles)},
                          {"no_overlap", share(t.motion.no_overlap, t.motion.vehicles)},
                          {"clear_of_ego", share(t.motion.clear_of_ego, t.motion.vehicles)}}},
              {"slow_rounds", t.slow_rounds},
              {"failures", t.failures}};
}

void draw_chart(const EvalArgs& a, const json& report) {
  std::vector<bench::ChartPoint> points;
  for (const auto& [name, c] : report["by_category"].items())
    points.push_back({name, c["mean_decision_latency_ms"].get<double>(), c["accuracy"].get<double>()});
  points.push_back({"all (" + report["backend"].get<std::string>() + ")", report["mean_decision_latency_ms"].get<double>(),
                    report["accuracy"].get<double>()});
  bench::write_scatter_png(a.chart, {"Decisions per category: " + std::filesystem::path(a.cases).filename().string(),
                                     "mean decision latency per round [ms]", "accuracy", true},
                           points);
}

int run_eval(const EvalArgs& a) {
  try {
    // Where the results go, checked before any work.
    if (!a.out.empty()) prepare_output_file(a.out);
    if (!a.chart.empty()) prepare_output_file(a.chart, "--chart");
    const auto cases = load_cases(a.cases, a.scene);
    std::map<std::string, scene::Scene> scenes;  // each scene loaded once, before any case runs
    std::vector<std::string> scene_names;
    for (const auto& c : cases)
      if (!scenes.contains(c.scene)) {
        scenes.emplace(c.scene, scene::load_scene(c.scene));
        scene_names.push_back(scenes.at(c.scene).name);
      }
    std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend(a.backend);
    agents::manager::Manager manager(agents::local_caller(backend), backend);
    Tally tally;
    for (const auto& c : cases) run_case(manager, scenes.at(c.scene), c, a, tally);
    const json report = make_report(a, backend->name(), cases.size(), scene_names, tally);
    std::cout << report.dump(1) << std::endl;
    if (!a.chart.empty()) draw_chart(a, report);
    if (!a.out.empty()) std::ofstream(a.out) << report.dump(1) << "\n";
    return exit_code::kOk;
  } catch (const scene::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
}

}  // namespace

void add_eval_command(CLI::App& app, int& result) {
  auto* eval = app.add_subcommand("eval", "Evaluations with measured accuracy and speed");
  eval->require_subcommand(1);
  add_eval_nvs_command(*eval, result);
  add_eval_light_command(*eval, result);
  add_eval_deletion_command(*eval, result);
  auto args = std::make_shared<EvalArgs>();
  auto* cmd = eval->add_subcommand(
      "commands", "Grade the decision pipeline on command cases (../shared/data/commands/README.md format): accuracy "
                  "per category and backend, mean decision latency, motion quality. Runs the agents in-process.");
  cmd->add_option("--cases", args->cases, "cases file (JSON lines)")->required();
  cmd->add_option("--scene", args->scene,
                  "scene directory the cases speak about (cases may name their own with a 'scene' field, a path "
                  "relative to the cases file)");
  cmd->add_option("--backend", args->backend, "LLM backend (default: $CHATSIM_LLM or offline)");
  cmd->add_option("--out", args->out, "also write the report here (e.g. bench/results/commands-dev.json)");
  cmd->add_option("--chart", args->chart, "also draw accuracy against latency per category as a PNG");
  cmd->add_option("--repeat", args->repeat,
                  "run each case this many times and time each round by its median (default: 1)")
      ->check(CLI::Range(1, 100));
  cmd->add_flag("--verbose,-v", args->verbose, "print each case's result to stderr");
  cmd->callback([args, &result] { result = run_eval(*args); });
}

}  // namespace chatsim::cli
