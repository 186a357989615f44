#pragma once
// What every agent process shares: common options, and serving an Agent on the bus.
// Each *_main.cpp is a few lines on top of this.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "agents/core/agent.hpp"
#include "agents/manager/manager.hpp"

namespace chatsim::bus {
class Node;
}

namespace chatsim::processes {

struct AgentProcessOptions {
  std::string bus;
  std::string name;
  std::string kind;
  int heartbeat_ms = 500;
  int handshake_timeout_ms = 10000;
  std::string curve_keys;  // folder with bus.pub and <name>.{pub,secret}: CURVE on the bus
  std::vector<std::string> allowed_roots;  // scene/output paths in requests must lie inside
};

// --bus, --name, --heartbeat-ms, --handshake-timeout-ms, --allowed-root, --curve-keys.
void add_node_options(CLI::App& app, AgentProcessOptions& options);

// Parses argv; returns -1 to go on, else the exit code to return (help: 0, bad usage: 2).
int parse_or_exit(CLI::App& app, int argc, char** argv);

// Makes the agent once the node exists (the manager calls the other agents through it).
using AgentFactory = std::function<std::unique_ptr<agents::Agent>(bus::Node& node)>;

// Serves the agent on the bus (requests on /agent/<kind>/request; the manager also serves
// /chat/request) until SIGINT/SIGTERM. Returns the process exit code.
int serve_agent(const AgentProcessOptions& options, const std::string& kind, const AgentFactory& make);

class AgentLiveness;

// Feeds every heartbeat on the node's bus into liveness (subscribe before node.start()).
void watch_heartbeats(bus::Node& node, AgentLiveness& liveness);

// Calls another agent over the bus: AgentRequest out, AgentResponse back, within timeout.
// With liveness, a call ends as soon as the agents it went to are dead or restarted.
agents::manager::AgentCaller bus_caller(bus::Node& node, std::chrono::milliseconds timeout,
                                        const AgentLiveness* liveness = nullptr);

// Spreads calls over the live processes of a kind (their worker topics), one call per worker at
// a time; a call whose worker dies is given to another. Needs liveness (heartbeats).
agents::manager::FanoutCaller bus_fanout_caller(bus::Node& node, std::chrono::milliseconds timeout, const AgentLiveness& liveness);

// The whole main() of an agent process with no options of its own.
int agent_main(int argc, char** argv, const std::string& kind);

}  // namespace chatsim::processes
