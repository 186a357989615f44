// chatsim: the user's command, with sub-commands in the spirit of ros2.
#include "common/util/exit_codes.hpp"
#include "processes/agent_process.hpp"
#include "processes/cli/command_errors.hpp"
#include "processes/cli/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app("chatsim: edit recorded driving scenes from natural-language commands");
  app.require_subcommand(1);
  int result = chatsim::exit_code::kOk;
  chatsim::cli::add_launch_command(app, result);
  chatsim::cli::add_bench_command(app, result);
  chatsim::cli::add_scene_command(app, result);
  chatsim::cli::add_plan_command(app, result);
  chatsim::cli::add_eval_command(app, result);
  chatsim::cli::add_topic_command(app, result);
  chatsim::cli::add_bag_command(app, result);
  chatsim::cli::add_keys_command(app, result);
  chatsim::cli::add_asset_command(app, result);
  chatsim::cli::add_radiance_commands(app, result);
  chatsim::cli::add_light_command(app, result);
  chatsim::cli::add_run_commands(app, result);
  chatsim::cli::add_serve_command(app, result);
  // A command that lets an exception out still ends with a message and a meaningful code.
  return chatsim::cli::exit_code_of([&] {
    if (const int code = chatsim::processes::parse_or_exit(app, argc, argv); code >= 0) return code;
    return result;
  });
}
