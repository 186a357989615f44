// chatsim run / chat: commands in, rendered results out, through every agent process. Progress
// of each stage (decisions, training, background, deletion, foreground, composition, encoding)
// is shown as it arrives from the agents.
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/scene/scene.hpp"
#include "common/util/clock.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/log.hpp"
#include "common/util/progress.hpp"
#include "processes/agent_liveness.hpp"
#include "processes/agent_process.hpp"
#include "processes/cli/commands.hpp"
#include "processes/cli/process_graph.hpp"

namespace chatsim::cli {
namespace {
namespace fs = std::filesystem;

const std::vector<std::string> kAllAgents{"manager", "view", "background", "deletion", "asset", "motion", "foreground"};

// One conversation with the manager over the bus, showing the progress it publishes.
class ChatSession {
 public:
  ChatSession(const std::string& bus, const std::string& scene, std::string conversation)
      : graph_(bus, kAllAgents), scene_(scene), conversation_(std::move(conversation)) {
    bus::NodeOptions o;
    o.name = "run-" + std::to_string(getpid());
    o.kind = "cli";
    o.curve = bus::curve_client_from_env();
    o.bus = graph_.endpoint();
    o.heartbeat_period = std::chrono::milliseconds(0);
    node_ = std::make_unique<bus::Node>(o);
    processes::watch_heartbeats(*node_, liveness_);
    node_->subscribe(std::string(bus::topics::kChatProgress), [this](const bus::Message& m) {
      const auto* p = m.payload<msgs::ChatProgress>();
      if (p == nullptr) return;
      const std::string stage(bus::view(p->stage()));
      if (!bar_ || stage != stage_) {
        if (bar_) bar_->finish();
        bar_ = std::make_unique<ProgressBar>(stage);
        stage_ = stage;
      }
      bar_->update(p->fraction(), std::string(bus::view(p->message())));
    });
    node_->dispatch_during_calls(std::string(bus::topics::kChatProgress));
    node_->start();
    for (const double until = mono_s() + 2.0; mono_s() < until && liveness_.snapshot("manager", mono_s()).empty();)
      node_->spin_once(std::chrono::milliseconds(20));
    if (conversation_.empty()) conversation_ = o.name;
  }

  // One round; true when it succeeded. Prints the manager's message and the result folder.
  bool round(const std::string& command, const std::string& out, double timeout_s, nlohmann::json* result = nullptr) {
    flatbuffers::FlatBufferBuilder fbb(1024);
    const std::string out_abs = out.empty() ? "" : fs::absolute(out).lexically_normal().string();
    const auto req = msgs::CreateChatRequestDirect(fbb, conversation_.c_str(), scene_.c_str(), command.c_str(), !out.empty(),
                                                   out_abs.c_str());
    const auto sent_to = liveness_.snapshot("manager", mono_s());
    bar_ = std::make_unique<ProgressBar>("decisions");
    stage_ = "decisions";
    bar_->update(0, "the agents decide");
    const auto r = node_->call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(),
                               std::chrono::milliseconds(int64_t(timeout_s * 1000)),
                               [&] { return liveness_.lost("manager", sent_to, mono_s()); });
    if (bar_) bar_->finish();
    bar_.reset();
    if (!r.ok()) {
      spdlog::error("no answer from the manager: {}", r.error_message);
      lost_ = true;
      return false;
    }
    const auto* resp = r.response->payload<msgs::ChatResponse>();
    if (resp == nullptr || !resp->ok()) {
      spdlog::error("{}", resp && resp->error() ? bus::view(resp->error()->message()) : "the manager failed");
      return false;
    }
    std::cerr << bus::view(resp->message()) << "\n";
    if (result != nullptr) {
      *result = nlohmann::json::parse(bus::view(resp->edit_state_json()));
      (*result)["output_dir"] = std::string(bus::view(resp->output_dir()));
    }
    if (!bus::view(resp->output_dir()).empty()) std::cout << "video: " << (fs::path(bus::view(resp->output_dir())) / "video.mp4").string() << std::endl;
    return true;
  }
  bool lost() const { return lost_; }
  ~ChatSession() {
    if (node_) node_->shutdown();
  }

 private:
  ProcessGraph graph_;
  std::string scene_, conversation_;
  std::unique_ptr<bus::Node> node_;
  processes::AgentLiveness liveness_;
  std::unique_ptr<ProgressBar> bar_;
  std::string stage_;
  bool lost_ = false;
};

struct RunArgs {
  std::string scene, out = "output/run", bus, conversation;
  std::vector<std::string> rounds;
  double timeout_s = 6 * 3600;
};

bool check_scene(const std::string& dir) {
  try {
    const auto s = scene::load_scene(dir);
    if (s.layout_only) {
      spdlog::error("{} is a layout-only scene: nothing to render (chatsim plan decides on it; chatsim scene demo "
                    "without --layout-only renders one)", dir);
      return false;
    }
    return true;
  } catch (const scene::SceneError& e) {
    spdlog::error("{}", e.what());
    return false;
  }
}

int run_run(const RunArgs& a) {
  init_logging("run");
  const std::string scene_dir = fs::absolute(a.scene).lexically_normal().string();
  if (!check_scene(scene_dir)) return exit_code::kUsage;
  try {
    ChatSession session(a.bus, scene_dir, a.conversation);
    // Every round but the last only decides; the last is rendered (earlier rounds' stages are
    // cached anyway when rendered by chat).
    for (size_t i = 0; i < a.rounds.size(); ++i) {
      const bool last = i + 1 == a.rounds.size();
      if (!session.round(a.rounds[i], last ? a.out : "", a.timeout_s))
        return session.lost() ? exit_code::kBusUnavailable : exit_code::kFailure;
    }
    return exit_code::kOk;
  } catch (const bus::BusError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kBusUnavailable;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return exit_code::kFailure;
  }
}

struct ChatArgs {
  std::string scene, out_root = "output/chat", bus;
  double timeout_s = 6 * 3600;
  bool no_render = false;
};

int run_chat(const ChatArgs& a) {
  init_logging("chat");
  const std::string scene_dir = fs::absolute(a.scene).lexically_normal().string();
  if (!check_scene(scene_dir)) return exit_code::kUsage;
  try {
    ChatSession session(a.bus, scene_dir, "");
    std::cerr << "chatsim chat: one command per line; each round's result goes to " << a.out_root
              << "/round-N; 'quit' ends.\n";
    int n = 0;
    for (std::string line;;) {
      std::cerr << "> " << std::flush;
      if (!std::getline(std::cin, line)) break;
      if (line == "quit" || line == "exit") break;
      if (line.find_first_not_of(" \t") == std::string::npos) continue;
      ++n;
      const std::string out = a.no_render ? "" : (fs::path(a.out_root) / ("round-" + std::to_string(n))).string();
      if (!session.round(line, out, a.timeout_s) && session.lost()) return exit_code::kBusUnavailable;
    }
    return exit_code::kOk;
  } catch (const bus::BusError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kBusUnavailable;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return exit_code::kFailure;
  }
}

}  // namespace

void add_run_commands(CLI::App& app, int& result) {
  auto ra = std::make_shared<RunArgs>();
  auto* run = app.add_subcommand("run", "Edit a scene from commands and render the result: multi-camera video, frames, "
                                        "depth, labels (JSON, KITTI) and edit.json in --out. Several commands are rounds of "
                                        "one conversation; the last is rendered. Starts the processes it needs when no bus "
                                        "is running, and stops them after.");
  run->add_option("--scene", ra->scene, "scene directory (with images)")->required();
  run->add_option("commands", ra->rounds, "the command(s), e.g. \"Remove all cars and add a red Porsche 20 m ahead\"")->required();
  run->add_option("--out", ra->out, "result folder (replaced; written whole or not at all)");
  run->add_option("--bus", ra->bus, "use this running bus instead of starting processes");
  run->add_option("--conversation", ra->conversation, "conversation id (default: a fresh one)");
  run->add_option("--timeout-s", ra->timeout_s, "how long to wait for the result (training on first use takes minutes)")
      ->check(CLI::PositiveNumber);
  run->callback([ra, &result] { result = run_run(*ra); });
  auto ca = std::make_shared<ChatArgs>();
  auto* chat = app.add_subcommand("chat", "A conversation on the terminal: each line is a round, rendered into "
                                          "--out-root/round-N (only what changed is rendered again)");
  chat->add_option("--scene", ca->scene, "scene directory (with images)")->required();
  chat->add_option("--out-root", ca->out_root, "folder for the rounds' results");
  chat->add_option("--bus", ca->bus, "use this running bus instead of starting processes");
  chat->add_option("--timeout-s", ca->timeout_s, "how long to wait for each round")->check(CLI::PositiveNumber);
  chat->add_flag("--no-render", ca->no_render, "decide only (print what the agents did)");
  chat->callback([ca, &result] { result = run_chat(*ca); });
}

}  // namespace chatsim::cli
