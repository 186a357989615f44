#pragma once
// A bus is named by one endpoint string; the proxy binds two sockets derived from it:
//   tcp://HOST:PORT   -> publishers connect to PORT, subscribers to PORT+1
//   ipc://PATH        -> PATH.pub and PATH.sub
//   inproc://NAME     -> NAME.pub and NAME.sub (tests and benchmarks in one process)
#include <string>

namespace chatsim::bus {

struct BusEndpoints {
  std::string publish;    // the proxy's XSUB side: nodes' PUB sockets connect here
  std::string subscribe;  // the proxy's XPUB side: nodes' SUB sockets connect here
};

// Throws std::invalid_argument naming the endpoint and what is wrong with it.
BusEndpoints split_bus_endpoint(const std::string& bus);

// Inverse of split_bus_endpoint for TCP: "tcp://HOST:PORT" from the publisher port.
std::string tcp_bus_endpoint(const std::string& host, int publish_port);

// True for tcp://HOST:0: only chatsim-bus may be given it; it picks the real ports.
bool asks_for_os_chosen_port(const std::string& bus);

// $CHATSIM_BUS if set, else tcp://127.0.0.1:7700.
std::string default_bus_endpoint();

}  // namespace chatsim::bus
