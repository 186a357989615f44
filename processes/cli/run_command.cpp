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
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"
#include "processes/cli/chat_session.hpp"
#include "processes/cli/process_graph.hpp"
#include "agents/manager/manager.hpp"
#include "common/util/output_dir.hpp"
#include "common/util/preset_names.hpp"

namespace chatsim::cli {
namespace {
namespace fs = std::filesystem;

struct RunArgs {
  std::string scene, out = "output/run", bus, conversation, preset = "fast";
  std::vector<std::string> rounds;
  double timeout_s = 6 * 3600;
  bool force = false;
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
  return exit_code_of([&] {
    agents::manager::check_render_output(a.out, scene_dir, a.force);  // before any process starts (exit 2)
    ChatSession session(a.bus, scene_dir, a.conversation);
    // Every round but the last only decides; the last is rendered.
    for (size_t i = 0; i < a.rounds.size(); ++i) {
      const bool last = i + 1 == a.rounds.size();
      const auto r = session.round(a.rounds[i], last ? a.out : "", a.timeout_s, a.preset, a.force);
      if (!r.ok) {
        spdlog::error("round {}: {}", i + 1, r.message);
        return session.lost() ? exit_code::kBusUnavailable : exit_code::kFailure;
      }
      std::cerr << "round " << i + 1 << ": " << r.message << "\n";
      if (!r.output_dir.empty()) std::cout << "video: " << (fs::path(r.output_dir) / "video.mp4").string() << std::endl;
    }
    return exit_code::kOk;
  }, log_error);
}

struct ChatArgs {
  std::string scene, out_root = "output/chat", bus, preset = "fast";
  double timeout_s = 6 * 3600;
  bool no_render = false, force = false;
};

int run_chat(const ChatArgs& a) {
  init_logging("chat");
  const std::string scene_dir = fs::absolute(a.scene).lexically_normal().string();
  if (!check_scene(scene_dir)) return exit_code::kUsage;
  return exit_code_of([&] {
    if (!a.no_render) prepare_rounds_root(a.out_root, scene_dir, a.force);  // before any process starts (exit 2)
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
      const auto r = session.round(line, out, a.timeout_s, a.preset, a.force);
      if (!r.ok) {
        spdlog::error("{}", r.message);
        if (session.lost()) return exit_code::kBusUnavailable;
        continue;
      }
      std::cerr << r.message << "\n";
      if (!r.output_dir.empty()) std::cout << "video: " << (fs::path(r.output_dir) / "video.mp4").string() << std::endl;
    }
    return exit_code::kOk;
  }, log_error);
}

}  // namespace

const char* const kPresetHelp =
    "rendering preset: draft (a quick look: small radiance field, 8 samples per pixel), fast (the default: 32) or quality "
    "(the largest radiance field, trained for long, 128)";

void add_run_commands(CLI::App& app, int& result) {
  auto ra = std::make_shared<RunArgs>();
  auto* run = app.add_subcommand("run", "Edit a scene from commands and render the result: multi-camera video, frames, "
                                        "depth, labels (JSON, KITTI) and edit.json in --out. Several commands are rounds of "
                                        "one conversation; the last is rendered. Starts the processes it needs when no bus "
                                        "is running, and stops them after.");
  run->add_option("--scene", ra->scene, "scene directory (with images)")->required();
  run->add_option("commands", ra->rounds, "the command(s), e.g. \"Remove all cars and add a red Porsche 20 m ahead\"")->required();
  run->add_option("--out", ra->out, "result folder: new, empty, or a result chatsim wrote (replaced when the new one is "
                                    "complete); any other folder is refused")
      ->capture_default_str();
  run->add_flag("--force", ra->force, kForceHelp);
  run->add_option("--bus", ra->bus, "use this running bus instead of starting processes");
  run->add_option("--conversation", ra->conversation, "conversation id (default: a fresh one)");
  run->add_option("--preset", ra->preset, kPresetHelp)->check(CLI::IsMember(preset_names()));
  run->add_option("--timeout-s", ra->timeout_s, "how long to wait for the result (training on first use takes minutes)")
      ->check(CLI::PositiveNumber);
  run->callback([ra, &result] { result = run_run(*ra); });
  auto ca = std::make_shared<ChatArgs>();
  auto* chat = app.add_subcommand("chat", "A conversation on the terminal: each line is a round, rendered into "
                                          "--out-root/round-N (only what changed is rendered again)");
  chat->add_option("--scene", ca->scene, "scene directory (with images)")->required();
  chat->add_option("--out-root", ca->out_root, kRoundsRootHelp)->capture_default_str();
  chat->add_flag("--force", ca->force, kForceHelp);
  chat->add_option("--bus", ca->bus, "use this running bus instead of starting processes");
  chat->add_option("--preset", ca->preset, kPresetHelp)->check(CLI::IsMember(preset_names()));
  chat->add_option("--timeout-s", ca->timeout_s, "how long to wait for each round")->check(CLI::PositiveNumber);
  chat->add_flag("--no-render", ca->no_render, "decide only (print what the agents did)");
  chat->callback([ca, &result] { result = run_chat(*ca); });
}

}  // namespace chatsim::cli
