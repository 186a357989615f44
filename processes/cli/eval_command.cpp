// chatsim eval commands: grade the decision pipeline on command cases (JSON lines).
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
  bool verbose = false;
};

struct Case {
  std::string id, category;
  std::vector<std::string> rounds;
  json expect;
};

std::vector<Case> load_cases(const std::string& file) {
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
    out.push_back({j["id"], j["category"], j["rounds"].get<std::vector<std::string>>(), j["expect"]});
  }
  return out;
}

int run_eval(const EvalArgs& a) {
  try {
    // Where the results go, checked before any work.
    if (!a.out.empty()) prepare_output_file(a.out);
    if (!a.chart.empty()) prepare_output_file(a.chart, "--chart");
    const auto cases = load_cases(a.cases);
    const auto scene = scene::load_scene(a.scene);
    std::shared_ptr<agents::llm::Backend> backend = agents::llm::make_backend(a.backend);
    agents::manager::Manager manager(agents::local_caller(backend), backend);
    std::map<std::string, std::pair<int, int>> by_category;
    std::map<std::string, std::pair<double, int>> latency_by_category;  // total ms, rounds
    json failures = json::array();
    double total_ms = 0;
    int rounds = 0, passed = 0;
    bench::MotionQuality motion;
    for (const auto& c : cases) {
      json state;
      bool error = false;
      std::string error_text;
      for (const auto& r : c.rounds) {
        const auto t0 = std::chrono::steady_clock::now();
        try {
          state = manager.chat(c.id, a.scene, r).edit_state;
        } catch (const std::exception& e) {
          error = true;
          error_text = e.what();
        }
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        total_ms += ms;
        ++rounds;
        latency_by_category[c.category].first += ms;
        latency_by_category[c.category].second++;
        if (error) break;
      }
      manager.reset(c.id);
      bool ok = !error;
      json case_fail = json::array();
      if (error) case_fail.push_back({{"check", "run"}, {"detail", error_text}});
      else
        for (const auto& r : bench::grade_case(scene, state, c.expect))
          if (!r.pass) {
            ok = false;
            case_fail.push_back({{"check", json::parse(r.check)}, {"detail", r.detail}});
          }
      if (!error) {
        const auto q = bench::motion_quality(scene, state);
        motion.vehicles += q.vehicles;
        motion.on_lane += q.on_lane;
        motion.action_match += q.action_match;
        motion.speed_match += q.speed_match;
      }
      auto& cat = by_category[c.category];
      cat.second++;
      if (ok) {
        cat.first++;
        ++passed;
      } else {
        failures.push_back({{"id", c.id}, {"rounds", c.rounds}, {"failed", case_fail}});
      }
      if (a.verbose) std::cerr << (ok ? "pass " : "FAIL ") << c.id << (ok ? "" : "  " + case_fail.dump()) << "\n";
    }
    json cats = json::object();
    for (const auto& [name, pt] : by_category)
      cats[name] = {{"passed", pt.first}, {"total", pt.second}, {"accuracy", double(pt.first) / pt.second},
                    {"mean_decision_latency_ms", latency_by_category[name].first / latency_by_category[name].second}};
    auto share = [](int k, int n) { return n ? double(k) / n : 1.0; };
    const json report{
        {"cases_file", a.cases},
        {"scene", scene.name},
        {"backend", backend->name()},
        {"cases", cases.size()},
        {"passed", passed},
        {"accuracy", share(passed, int(cases.size()))},
        {"by_category", cats},
        {"by_backend", {{backend->name(), share(passed, int(cases.size()))}}},
        {"mean_decision_latency_ms", rounds ? total_ms / rounds : 0.0},
        {"motion", {{"vehicles", motion.vehicles}, {"on_lane", share(motion.on_lane, motion.vehicles)},
                    {"action_match", share(motion.action_match, motion.vehicles)},
                    {"speed_match", share(motion.speed_match, motion.vehicles)}}},
        {"failures", failures}};
    std::cout << report.dump(1) << std::endl;
    if (!a.chart.empty()) {
      std::vector<bench::ChartPoint> points;
      for (const auto& [name, c] : cats.items())
        points.push_back({name, c["mean_decision_latency_ms"].get<double>(), c["accuracy"].get<double>()});
      points.push_back({"all (" + backend->name() + ")", report["mean_decision_latency_ms"].get<double>(),
                        report["accuracy"].get<double>()});
      bench::write_scatter_png(a.chart, {"Decisions per category: " + std::filesystem::path(a.cases).filename().string(),
                                         "mean decision latency per round [ms]", "accuracy", true},
                               points);
    }
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
  cmd->add_option("--scene", args->scene, "scene directory the cases speak about")->required();
  cmd->add_option("--backend", args->backend, "LLM backend (default: $CHATSIM_LLM or offline)");
  cmd->add_option("--out", args->out, "also write the report here (e.g. bench/results/commands-dev.json)");
  cmd->add_option("--chart", args->chart, "also draw accuracy against latency per category as a PNG");
  cmd->add_flag("--verbose,-v", args->verbose, "print each case's result to stderr");
  cmd->callback([args, &result] { result = run_eval(*args); });
}

}  // namespace chatsim::cli
