#pragma once
// The `chatsim` command's sub-commands, each registering itself on the CLI11 app and
// returning its exit code through the callback's result.
#include <CLI/CLI.hpp>

namespace chatsim::cli {

// The --force flag of every command that writes an output folder (common/util/output_dir.hpp).
inline constexpr const char* kForceHelp =
    "replace an output folder chatsim wrote of another kind, or one an earlier chatsim wrote without its marker; never "
    "a folder chatsim did not write";

// Each adds a sub-command; `result` receives the exit code when it runs.
void add_launch_command(CLI::App& app, int& result);
void add_bench_command(CLI::App& app, int& result);
void add_scene_command(CLI::App& app, int& result);
void add_plan_command(CLI::App& app, int& result);
void add_eval_command(CLI::App& app, int& result);
void add_topic_command(CLI::App& app, int& result);
void add_bag_command(CLI::App& app, int& result);
void add_keys_command(CLI::App& app, int& result);
void add_asset_command(CLI::App& app, int& result);
void add_radiance_commands(CLI::App& app, int& result);  // train, render
void add_eval_nvs_command(CLI::App& eval, int& result);
void add_light_command(CLI::App& app, int& result);
void add_eval_light_command(CLI::App& eval, int& result);
void add_eval_deletion_command(CLI::App& eval, int& result);
void add_run_commands(CLI::App& app, int& result);  // run, chat
void add_serve_command(CLI::App& app, int& result);
void add_render_bench_commands(CLI::App& bench, int& result);  // bench foreground, light, deletion, nvs
void add_e2e_bench_command(CLI::App& bench, int& result);       // bench e2e

}  // namespace chatsim::cli
