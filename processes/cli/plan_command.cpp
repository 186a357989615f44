// chatsim plan: the decision pipeline through the bus (manager, view, deletion, asset, motion),
// one round per command argument, printing the final edit state as JSON.
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/scene/scene.hpp"
#include "common/util/clock.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/log.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"
#include "processes/agent_liveness.hpp"
#include "processes/agent_process.hpp"
#include "processes/cli/process_graph.hpp"

namespace chatsim::cli {
namespace {

struct PlanArgs {
  std::string scene;
  std::vector<std::string> rounds;
  std::string bus;
  std::string conversation;
  double timeout_s = 120;
};

int run_plan(const PlanArgs& a) {
  init_logging("plan");
  const std::string scene_dir = std::filesystem::absolute(a.scene).lexically_normal().string();
  try {
    scene::load_scene(scene_dir);  // a bad scene is reported before any process starts
  } catch (const scene::SceneError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kUsage;
  }
  return exit_code_of([&] {
    ProcessGraph graph(a.bus, {"manager", "view", "deletion", "asset", "motion"});
    bus::NodeOptions o;
    o.name = "plan-" + std::to_string(getpid());
    o.kind = "cli";
    o.curve = bus::curve_client_from_env();
    o.bus = graph.endpoint();
    o.heartbeat_period = std::chrono::milliseconds(0);
    bus::Node node(o);
    // The manager's heartbeats: if it dies mid-round we say so at once, not at the deadline.
    processes::AgentLiveness liveness;
    processes::watch_heartbeats(node, liveness);
    node.start();
    for (const double until = mono_s() + 1.0; mono_s() < until && liveness.snapshot("manager", mono_s()).empty();)
      node.spin_once(std::chrono::milliseconds(20));
    const std::string conversation = a.conversation.empty() ? o.name : a.conversation;
    std::string edit;
    for (size_t i = 0; i < a.rounds.size(); ++i) {
      flatbuffers::FlatBufferBuilder fbb(1024);
      const auto req = msgs::CreateChatRequestDirect(fbb, conversation.c_str(), scene_dir.c_str(), a.rounds[i].c_str(), false, "");
      const auto sent_to = liveness.snapshot("manager", mono_s());
      const auto result = node.call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(),
                                    std::chrono::milliseconds(int64_t(a.timeout_s * 1000)),
                                    [&] { return liveness.lost("manager", sent_to, mono_s()); });
      if (!result.ok()) {
        spdlog::error("round {}: no answer from the manager: {}", i + 1, result.error_message);
        return exit_code::kBusUnavailable;
      }
      const auto* resp = result.response->payload<msgs::ChatResponse>();
      if (resp == nullptr) {
        spdlog::error("round {}: the manager sent no ChatResponse", i + 1);
        return exit_code::kFailure;
      }
      if (!resp->ok()) {
        spdlog::error("round {}: {}", i + 1, resp->error() ? bus::view(resp->error()->message()) : "failed");
        return exit_code::kFailure;
      }
      std::cerr << "round " << i + 1 << ": " << bus::view(resp->message()) << "\n";
      edit = std::string(bus::view(resp->edit_state_json()));
    }
    node.shutdown();
    std::cout << nlohmann::json::parse(edit).dump(1) << std::endl;
    return exit_code::kOk;
  }, log_error);
}

}  // namespace

void add_plan_command(CLI::App& app, int& result) {
  auto args = std::make_shared<PlanArgs>();
  auto* cmd = app.add_subcommand(
      "plan", "Decide an edit without rendering: send each command (one per round of one conversation) through the "
              "manager and the view, deletion, asset and motion agents, and print the edit state JSON. Starts the "
              "processes it needs when no bus is running, and stops them after.");
  cmd->add_option("--scene", args->scene, "scene directory (chatsim-scene/1)")->required();
  cmd->add_option("commands", args->rounds, "the commands, one per round, e.g. \"Add a red car 20 m ahead\"")->required();
  cmd->add_option("--bus", args->bus, "use this running bus instead of starting processes");
  cmd->add_option("--conversation", args->conversation, "conversation id (default: a fresh one)");
  cmd->add_option("--timeout-s", args->timeout_s, "how long to wait for each round")->check(CLI::PositiveNumber);
  cmd->callback([args, &result] { result = run_plan(*args); });
}

}  // namespace chatsim::cli
