#include <unistd.h>

#include <filesystem>

#include <spdlog/spdlog.h>

#include "common/launch/launcher.hpp"
#include "common/util/executable_dir.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/log.hpp"
#include "common/util/signals.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct LaunchArgs {
  std::string file;
  std::string bus;
  std::string endpoint_file;
  std::vector<std::string> mocks;
  bool check = false;
};

int run_launch(const LaunchArgs& a) {
  init_logging("launch");
  const auto& stop = install_stop_signals();
  try {
    auto file = launch::load_launch_file(a.file);
    for (const auto& m : a.mocks) {
      const auto eq = m.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == m.size()) {
        spdlog::error("--mock '{}': expected NAME=SCRIPT, e.g. motion=launch/mocks/motion.yaml", m);
        return exit_code::kUsage;
      }
      launch::swap_for_mock(file, m.substr(0, eq), m.substr(eq + 1));
    }
    if (a.check) {
      std::printf("%s: %zu processes, bus %s\n", a.file.c_str(), file.processes.size(),
                  file.bus.c_str());
      return exit_code::kOk;
    }
    launch::Launcher launcher(std::move(file), {a.bus, a.endpoint_file, executable_dir()});
    return launcher.run(stop);
  } catch (const launch::LaunchFileError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kUsage;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return exit_code::kFailure;
  }
}

}  // namespace

void add_launch_command(CLI::App& app, int& result) {
  auto args = std::make_shared<LaunchArgs>();
  auto* cmd = app.add_subcommand(
      "launch",
      "Start a process graph from a YAML launch file (see launch/local.yaml); Ctrl-C stops "
      "everything it started");
  cmd->add_option("file", args->file, "launch file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--bus", args->bus, "bus endpoint, overriding the file's (port 0: OS-chosen)");
  cmd->add_option("--endpoint-file", args->endpoint_file, "write the bus endpoint here once it is up");
  cmd->add_option("--mock", args->mocks, "NAME=SCRIPT: run chatsim-mock with SCRIPT in place of NAME");
  cmd->add_flag("--check", args->check, "only validate the file (and --mock swaps), start nothing");
  cmd->callback([args, &result] { result = run_launch(*args); });
}

}  // namespace chatsim::cli
