#include "processes/cli/process_graph.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>

#include <spdlog/spdlog.h>

#include "common/bus/endpoint.hpp"
#include "common/bus/node.hpp"
#include "common/launch/launcher.hpp"
#include "common/util/executable_dir.hpp"

namespace chatsim::cli {
namespace fs = std::filesystem;

namespace {

bool bus_answers(const std::string& endpoint) {
  try {
    bus::NodeOptions o;
    o.name = "cli-probe-" + std::to_string(getpid());
    o.kind = "cli";
  o.curve = bus::curve_client_from_env();
    o.curve = bus::curve_client_from_env();
    o.bus = endpoint;
    o.heartbeat_period = std::chrono::milliseconds(0);
    o.handshake_timeout = std::chrono::milliseconds(300);
    bus::Node node(o);
    node.start();
    node.shutdown();
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

ProcessGraph::ProcessGraph(const std::string& bus, const std::vector<std::string>& agents) {
  if (!bus.empty()) {
    endpoint_ = bus;
    return;
  }
  if (const char* env = std::getenv("CHATSIM_BUS"); env != nullptr && *env != '\0' && bus_answers(env)) {
    endpoint_ = env;
    return;
  }
  launch::LaunchFile file;
  file.bus = "tcp://127.0.0.1:0";
  // With $CHATSIM_CURVE_KEYS the private graph is secured with those keys too.
  if (const char* keys = std::getenv("CHATSIM_CURVE_KEYS"); keys != nullptr && *keys != '\0') file.curve_keys = keys;
  file.stop_timeout_s = 2;
  launch::ProcessSpec proxy;
  proxy.name = "bus";
  proxy.kind = "bus";
  proxy.executable = "chatsim-bus";
  file.processes.push_back(proxy);
  for (const auto& a : agents) {
    launch::ProcessSpec p;
    p.name = a;
    p.kind = a;
    p.executable = "chatsim-" + a;
    file.processes.push_back(p);
  }
  endpoint_file_ = fs::temp_directory_path() / ("chatsim-bus-" + std::to_string(getpid()) + ".endpoint");
  fs::remove(endpoint_file_);
  launcher_ = std::make_unique<launch::Launcher>(std::move(file), launch::LauncherOptions{"", endpoint_file_, executable_dir()});
  spdlog::info("no bus running: starting chatsim-bus and {} agent processes", agents.size());
  thread_ = std::thread([this] { exit_code_ = launcher_->run(stop_); });
  // Ready when the endpoint file exists and every process has beaten (the launcher starts them
  // in order, so a heartbeat from the last one means all are up).
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline && exit_code_ < 0) {
    std::ifstream in(endpoint_file_);
    if (in && std::getline(in, endpoint_) && !endpoint_.empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (endpoint_.empty()) {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    throw std::runtime_error("could not start the bus and agents (see the messages above)");
  }
  // The launcher writes the endpoint once the proxy is up; wait for the last agent's heartbeat.
  bus::NodeOptions o;
  o.name = "cli-wait-" + std::to_string(getpid());
  o.kind = "cli";
  o.curve = bus::curve_client_from_env();
  o.bus = endpoint_;
  o.heartbeat_period = std::chrono::milliseconds(0);
  bus::Node node(o);
  std::vector<std::string> seen;
  node.subscribe("/bus/heartbeat", [&](const bus::Message& m) {
    const auto* hb = m.payload<msgs::Heartbeat>();
    if (hb != nullptr && hb->node() != nullptr) seen.push_back(hb->node()->str());
  });
  node.start();
  const std::string last = agents.empty() ? "bus" : agents.back();
  while (std::chrono::steady_clock::now() < deadline && exit_code_ < 0) {
    node.spin_once(std::chrono::milliseconds(50));
    if (std::find(seen.begin(), seen.end(), last) != seen.end()) return;
  }
  node.shutdown();
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  throw std::runtime_error("the agent processes did not come up within 30 s");
}

ProcessGraph::~ProcessGraph() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
  if (!endpoint_file_.empty()) {
    std::error_code ec;
    fs::remove(endpoint_file_, ec);
  }
}

}  // namespace chatsim::cli
