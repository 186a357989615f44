#pragma once
// Launch files (YAML): which processes to start, where, with what, and how to keep them up.
// Parsing is strict: unknown keys, wrong types and bad values are refused with FILE:LINE:COL.
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/launch/backoff.hpp"

namespace chatsim::launch {

class LaunchFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Readiness { Heartbeat, None };

struct ProcessSpec {
  std::string name;                 // unique; also the node's --name
  std::string kind;                 // agent kind ("motion"); "bus" for the proxy
  std::string executable;           // bare names are looked up beside chatsim, then in PATH
  std::vector<std::string> args;
  std::map<std::string, std::string> env;
  std::string host;                 // empty or "localhost": this machine; else started over ssh
  std::string netns;                // a network namespace on this machine (ip netns exec): a "host" for tests
  RespawnPolicy respawn = RespawnPolicy::OnFailure;
  BackoffConfig backoff;
  Readiness ready = Readiness::Heartbeat;
  double ready_timeout_s = 10.0;
  bool bus_args = true;             // pass --bus and --name
  std::optional<std::filesystem::path> mock_script;  // run chatsim-mock in its place
  int line = 0;                     // where it was declared, for messages
};

struct LaunchFile {
  std::filesystem::path path;
  std::string bus;                  // bus endpoint; port 0 = OS-chosen
  double stop_timeout_s = 3.0;      // SIGTERM, then SIGKILL after this
  std::filesystem::path curve_keys; // CURVE keys folder: every process gets --curve-keys
  std::vector<std::filesystem::path> allowed_roots;  // every process gets --allowed-root for each
  std::vector<ProcessSpec> processes;

  const ProcessSpec* find(const std::string& name) const;
};

LaunchFile load_launch_file(const std::filesystem::path& path);
// For tests and tools: parse text as if read from `path_for_messages`.
LaunchFile parse_launch_file(const std::string& text, const std::filesystem::path& path_for_messages);

// Replaces the process `name` by chatsim-mock answering its requests from `script`.
// Throws LaunchFileError if there is no such process.
void swap_for_mock(LaunchFile& file, const std::string& name, const std::filesystem::path& script);

}  // namespace chatsim::launch
