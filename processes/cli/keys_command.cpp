// chatsim keys new: CURVE key pairs for a secured bus.
#include <iostream>

#include "common/bus/curve.hpp"
#include "common/util/exit_codes.hpp"
#include "processes/cli/commands.hpp"

namespace chatsim::cli {
namespace {

struct KeysArgs {
  std::string dir;
  std::vector<std::string> names;
};

int run_new(const KeysArgs& a) {
  try {
    for (const auto& name : a.names) {
      bus::write_curve_keys(a.dir, name, bus::generate_curve_keys());
      std::cout << a.dir << "/" << name << ".pub, " << name << ".secret\n";
    }
    return exit_code::kOk;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return exit_code::kFailure;
  }
}

}  // namespace

void add_keys_command(CLI::App& app, int& result) {
  auto* keys = app.add_subcommand("keys", "CURVE keys: an encrypted bus that admits only known nodes");
  keys->require_subcommand(1);
  auto args = std::make_shared<KeysArgs>();
  auto* make = keys->add_subcommand(
      "new", "Make key pairs in a folder. The proxy needs 'bus', chatsim launch needs 'launch', command-line "
             "tools 'cli', every other process one named as the process. The proxy admits every <name>.pub there; "
             "give a host only its own .secret.");
  make->add_option("--dir", args->dir, "keys folder")->required();
  make->add_option("names", args->names, "key names, e.g. bus launch cli manager view ...")->required();
  make->callback([args, &result] { result = run_new(*args); });
}

}  // namespace chatsim::cli
