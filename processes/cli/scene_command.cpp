// chatsim scene info: validate a scene directory and summarise it.
#include <iostream>

#include <spdlog/spdlog.h>

#include "common/scene/scene.hpp"
#include "common/scene/scene_summary.hpp"
#include "common/util/exit_codes.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct SceneInfoArgs {
  std::string dir;
  bool json = false;
};

int run_info(const SceneInfoArgs& a) {
  try {
    const auto scene = scene::load_scene(a.dir);
    const auto summary = scene::summarize(scene);
    if (a.json) std::cout << summary.dump(1) << "\n";
    else std::cout << scene::summary_text(summary);
    return exit_code::kOk;
  } catch (const scene::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kUsage;
  }
}

}  // namespace

void add_scene_command(CLI::App& app, int& result) {
  auto* scene = app.add_subcommand("scene", "Scenes: inspect (info); import and demo come with issue #4's remaining parts");
  scene->require_subcommand(1);
  auto args = std::make_shared<SceneInfoArgs>();
  auto* info = scene->add_subcommand("info", "Validate a scene directory and print a summary (cameras, frames, extent, "
                                             "objects by category, lanes); errors name the file and field");
  info->add_option("dir", args->dir, "scene directory")->required();
  info->add_flag("--json", args->json, "print the summary as JSON");
  info->callback([args, &result] { result = run_info(*args); });
}

}  // namespace chatsim::cli
