// chatsim-mock: stands in for any agent, answering its requests from a script.
#include <iostream>

#include <spdlog/spdlog.h>

#include "agents/mock/mock_script.hpp"
#include "common/bag/recorded_exchanges.hpp"
#include "common/util/exit_codes.hpp"
#include "processes/agent_process.hpp"

int main(int argc, char** argv) {
  using namespace chatsim;
  CLI::App app("chatsim-mock: answers one agent's requests from a script of canned responses "
               "(YAML or JSON, with optional delay and failure injection) or from a recording (--bag)");
  processes::AgentProcessOptions options;
  std::string agent;
  std::string script_path;
  app.add_option("--agent", agent, "agent kind to stand in for (manager, view, motion, ...); "
                                   "default: the script's 'agent'");
  std::string bag_path;
  auto* script_opt = app.add_option("--script", script_path, "the script file")->check(CLI::ExistingFile);
  auto* bag_opt = app.add_option("--bag", bag_path, "answer as the agent did in this MCAP recording (needs --agent)")
                      ->check(CLI::ExistingFile);
  script_opt->excludes(bag_opt);
  processes::add_node_options(app, options);
  if (const int code = processes::parse_or_exit(app, argc, argv); code >= 0) return code;
  if (script_path.empty() == bag_path.empty()) {
    std::cerr << "chatsim-mock: give --script FILE or --bag FILE --agent KIND\n";
    return exit_code::kUsage;
  }
  if (!bag_path.empty()) {
    if (agent.empty()) {
      std::cerr << "chatsim-mock: --bag needs --agent (which agent's answers to replay)\n";
      return exit_code::kUsage;
    }
    try {
      auto exchanges = bag::recorded_exchanges(bag_path, agent);
      spdlog::info("{}: {} recorded {} exchanges", bag_path, exchanges.size(), agent);
      return processes::serve_agent(options, agent, [exchanges, agent](bus::Node&) {
        return std::make_unique<agents::ReplayAgent>(agent, exchanges);
      });
    } catch (const std::exception& e) {
      spdlog::error("{}: {}", bag_path, e.what());
      return exit_code::kUsage;
    }
  }
  try {
    auto script = agents::load_mock_script(script_path);
    if (!agent.empty() && agent != script.agent) {
      spdlog::error("{}: the script answers for agent '{}', but --agent is '{}'", script_path,
                    script.agent, agent);
      return exit_code::kUsage;
    }
    const std::string kind = script.agent;
    auto shared = std::make_shared<agents::MockScript>(std::move(script));
    return processes::serve_agent(options, kind, [shared](bus::Node&) {
      return std::make_unique<agents::MockAgent>(std::move(*shared));
    });
  } catch (const agents::MockScriptError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kUsage;
  }
}
