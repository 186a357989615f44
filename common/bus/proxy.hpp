#pragma once
// The bus proxy (XSUB/XPUB): publishers connect to one side, subscribers to the other;
// subscriptions flow upstream, messages downstream, frames are moved, never copied.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include <zmq.hpp>

#include "common/bus/curve.hpp"

namespace chatsim::bus {

struct ProxyStats {
  std::atomic<uint64_t> messages{0};
  std::atomic<uint64_t> bytes{0};
  std::atomic<uint64_t> subscription_changes{0};
};

class Proxy {
 public:
  // Binds both sockets. A tcp endpoint with port 0 gets an OS-chosen pair of adjacent ports;
  // endpoint() then tells which. Throws zmq::error_t / std::invalid_argument on failure.
  // With curve enabled, both sides encrypt and admit only the authorized public keys.
  Proxy(std::shared_ptr<zmq::context_t> context, const std::string& bus, int hwm = 1000, const CurveServer& curve = {});
  ~Proxy();

  // The bus endpoint nodes should use (the real port when 0 was asked for).
  const std::string& endpoint() const { return endpoint_; }

  // Forwards until stop becomes true (checked every 100 ms).
  void run(const std::atomic<bool>& stop);

  const ProxyStats& stats() const { return stats_; }
  uint64_t refused_connections() const { return zap_ ? zap_->refused() : 0; }

 private:
  std::shared_ptr<zmq::context_t> context_;
  std::unique_ptr<ZapAuthenticator> zap_;  // before the sockets: it must outlive them
  std::unique_ptr<zmq::socket_t> xsub_;
  std::unique_ptr<zmq::socket_t> xpub_;
  std::string endpoint_;
  ProxyStats stats_;
};

}  // namespace chatsim::bus
