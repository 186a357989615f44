#pragma once
// An in-process bus proxy on an OS-chosen loopback port, for tests.
#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "common/bus/node.hpp"
#include "common/bus/proxy.hpp"

namespace chatsim::test_support {

class InProcessBus {
 public:
  InProcessBus()
      : context_(std::make_shared<zmq::context_t>(1)),
        proxy_(context_, "tcp://127.0.0.1:0"),
        thread_([this] { proxy_.run(stop_); }) {}
  ~InProcessBus() {
    stop_.store(true);
    thread_.join();
  }
  const std::string& endpoint() const { return proxy_.endpoint(); }
  std::shared_ptr<zmq::context_t> context() const { return context_; }
  const bus::ProxyStats& proxy_stats() const { return proxy_.stats(); }

  bus::NodeOptions options(const std::string& name, int heartbeat_ms = 0) const {
    bus::NodeOptions o;
    o.name = name;
    o.kind = "test";
    o.bus = endpoint();
    o.heartbeat_period = std::chrono::milliseconds(heartbeat_ms);
    o.handshake_timeout = std::chrono::seconds(5);
    return o;
  }

 private:
  std::shared_ptr<zmq::context_t> context_;
  bus::Proxy proxy_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Spins node until pred() or timeout; true if pred() became true.
template <class Pred>
bool spin_until(bus::Node& node, Pred pred, std::chrono::milliseconds timeout = std::chrono::seconds(5)) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (!pred() && std::chrono::steady_clock::now() < end) node.spin_once(std::chrono::milliseconds(10));
  return pred();
}

}  // namespace chatsim::test_support
