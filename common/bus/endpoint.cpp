#include "common/bus/endpoint.hpp"

#include <charconv>
#include <cstdlib>
#include <stdexcept>

namespace chatsim::bus {
namespace {

[[noreturn]] void bad(const std::string& bus, const std::string& why) {
  throw std::invalid_argument("bus endpoint '" + bus + "': " + why +
                              " (expected tcp://HOST:PORT, ipc://PATH or inproc://NAME)");
}

}  // namespace

BusEndpoints split_bus_endpoint(const std::string& bus) {
  const auto scheme_end = bus.find("://");
  if (scheme_end == std::string::npos) bad(bus, "no scheme");
  const std::string scheme = bus.substr(0, scheme_end);
  const std::string rest = bus.substr(scheme_end + 3);
  if (rest.empty()) bad(bus, "nothing after the scheme");
  if (scheme == "ipc" || scheme == "inproc") {
    return {bus + ".pub", bus + ".sub"};
  }
  if (scheme != "tcp") bad(bus, "unsupported scheme '" + scheme + "'");
  const auto colon = rest.rfind(':');
  if (colon == std::string::npos || colon == 0) bad(bus, "missing HOST:PORT");
  const std::string host = rest.substr(0, colon);
  const std::string port_text = rest.substr(colon + 1);
  int port = -1;
  const auto [ptr, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc() || ptr != port_text.data() + port_text.size() || port < 0 || port > 65534) {
    bad(bus, "port '" + port_text + "' is not a number from 0 to 65534");
  }
  if (port == 0) bad(bus, "port 0 (OS-chosen) is only valid for chatsim-bus --bus; give nodes the real port");
  return {"tcp://" + host + ":" + std::to_string(port), "tcp://" + host + ":" + std::to_string(port + 1)};
}

std::string tcp_bus_endpoint(const std::string& host, int publish_port) {
  return "tcp://" + host + ":" + std::to_string(publish_port);
}

bool asks_for_os_chosen_port(const std::string& bus) {
  return bus.rfind("tcp://", 0) == 0 && bus.size() > 2 && bus.compare(bus.size() - 2, 2, ":0") == 0;
}

std::string default_bus_endpoint() {
  if (const char* env = std::getenv("CHATSIM_BUS"); env != nullptr && *env != '\0') return env;
  return "tcp://127.0.0.1:7700";
}

}  // namespace chatsim::bus
