// chatsim-bus: the bus proxy every node connects to (like a ROS master, but only forwarding).
#include <filesystem>
#include <fstream>
#include <thread>

#include <spdlog/spdlog.h>

#include "common/bus/endpoint.hpp"
#include "common/bus/node.hpp"
#include "common/bus/proxy.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/log.hpp"
#include "common/util/signals.hpp"
#include "processes/agent_process.hpp"

int main(int argc, char** argv) {
  using namespace chatsim;
  CLI::App app("chatsim-bus: the message bus proxy (ZeroMQ XSUB/XPUB). Publishers connect to the "
               "endpoint's port, subscribers to port+1. Give port 0 to let the OS choose.");
  processes::AgentProcessOptions options;
  std::string endpoint_file;
  int hwm = 1000;
  processes::add_node_options(app, options);
  app.add_option("--endpoint-file", endpoint_file, "write the bound endpoint here once listening");
  app.add_option("--hwm", hwm, "per-connection queue limit in messages")->check(CLI::Range(1, 1000000));
  if (const int code = processes::parse_or_exit(app, argc, argv); code >= 0) return code;

  const auto& stop = install_stop_signals();
  const std::string name = options.name.empty() ? "bus" : options.name;
  init_logging(name);
  const std::string requested = options.bus.empty() ? bus::default_bus_endpoint() : options.bus;
  try {
    auto context = std::make_shared<zmq::context_t>(1);
    bus::CurveServer curve;
    if (!options.curve_keys.empty()) curve = bus::curve_server_from_dir(options.curve_keys);
    bus::Proxy proxy(context, requested, hwm, curve);
    if (curve.enabled())
      spdlog::info("CURVE on: {} authorized keys from {}", curve.authorized.size(), options.curve_keys);
    std::atomic<bool> proxy_stop{false};
    std::thread forwarding([&] { proxy.run(proxy_stop); });

    // Its own node proves the proxy forwards, then beats like every other process.
    bus::NodeOptions no;
    no.name = name;
    no.kind = "bus";
    no.bus = proxy.endpoint();
    no.heartbeat_period = std::chrono::milliseconds(options.heartbeat_ms);
    if (curve.enabled()) no.curve = bus::curve_client_from_dir(options.curve_keys, "bus");
    bus::Node node(no, context);
    node.start();
    if (!endpoint_file.empty()) {  // written whole, then renamed: readers never see half of it
      const std::string tmp = endpoint_file + ".tmp";
      std::ofstream(tmp) << proxy.endpoint() << "\n";
      std::filesystem::rename(tmp, endpoint_file);
    }
    spdlog::info("bus proxy on {} (publishers) / +1 (subscribers)", proxy.endpoint());
    node.spin(stop);
    node.shutdown();
    proxy_stop.store(true);
    forwarding.join();
    spdlog::info("stopped after forwarding {} messages ({} bytes)", proxy.stats().messages.load(),
                 proxy.stats().bytes.load());
  } catch (const zmq::error_t& e) {
    spdlog::error("cannot listen on {}: {}", requested, e.what());
    return exit_code::kBusUnavailable;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return exit_code::kUsage;
  }
  return exit_code::kOk;
}
