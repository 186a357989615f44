// chatsim-mock: stands in for any agent, answering its requests from a script.
#include <spdlog/spdlog.h>

#include "agents/mock/mock_script.hpp"
#include "common/util/exit_codes.hpp"
#include "processes/agent_process.hpp"

int main(int argc, char** argv) {
  using namespace chatsim;
  CLI::App app("chatsim-mock: answers one agent's requests from a script of canned responses "
               "(YAML or JSON), with optional delay and failure injection");
  processes::AgentProcessOptions options;
  std::string agent;
  std::string script_path;
  app.add_option("--agent", agent, "agent kind to stand in for (manager, view, motion, ...); "
                                   "default: the script's 'agent'");
  app.add_option("--script", script_path, "the script file")->required()->check(CLI::ExistingFile);
  processes::add_node_options(app, options);
  if (const int code = processes::parse_or_exit(app, argc, argv); code >= 0) return code;
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
