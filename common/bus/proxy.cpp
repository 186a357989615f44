#include "common/bus/proxy.hpp"

#include <cerrno>
#include <optional>
#include <stdexcept>

#include "common/bus/endpoint.hpp"

namespace chatsim::bus {
namespace {

int port_of(const std::string& endpoint) {
  return std::stoi(endpoint.substr(endpoint.rfind(':') + 1));
}

std::unique_ptr<zmq::socket_t> make_socket(zmq::context_t& ctx, zmq::socket_type type, int hwm, const CurveServer& curve) {
  auto s = std::make_unique<zmq::socket_t>(ctx, type);
  s->set(zmq::sockopt::linger, 0);
  s->set(zmq::sockopt::sndhwm, hwm);
  s->set(zmq::sockopt::rcvhwm, hwm);
  if (curve.enabled()) {
    s->set(zmq::sockopt::curve_secretkey, curve.secret_key);
    apply_curve_server(*s);
  }
  return s;
}

// Moves every frame of one multipart message from `from` to `to`; nullopt when none waits.
std::optional<size_t> forward(zmq::socket_t& from, zmq::socket_t& to) {
  size_t bytes = 0;
  bool first = true;
  for (;;) {
    zmq::message_t frame;
    const auto flags = first ? zmq::recv_flags::dontwait : zmq::recv_flags::none;
    if (!from.recv(frame, flags)) return std::nullopt;
    first = false;
    const bool more = frame.more();
    bytes += frame.size();
    to.send(frame, more ? zmq::send_flags::sndmore : zmq::send_flags::none);
    if (!more) return bytes;
  }
}

}  // namespace

Proxy::~Proxy() = default;

Proxy::Proxy(std::shared_ptr<zmq::context_t> context, const std::string& bus, int hwm, const CurveServer& curve)
    : context_(std::move(context)) {
  if (curve.enabled()) zap_ = std::make_unique<ZapAuthenticator>(*context_, curve.authorized);
  if (asks_for_os_chosen_port(bus)) {
    // OS-chosen ports: take the XSUB port the OS gives, try the next one for XPUB.
    const std::string host = bus.substr(6, bus.size() - 6 - 2);  // between "tcp://" and ":0"

    for (int attempt = 0; attempt < 50 && endpoint_.empty(); ++attempt) {
      xsub_ = make_socket(*context_, zmq::socket_type::xsub, hwm, curve);
      xsub_->bind("tcp://" + host + ":0");
      const int port = port_of(xsub_->get(zmq::sockopt::last_endpoint));
      if (port >= 65535) continue;
      xpub_ = make_socket(*context_, zmq::socket_type::xpub, hwm, curve);
      try {
        xpub_->bind("tcp://" + host + ":" + std::to_string(port + 1));
        endpoint_ = tcp_bus_endpoint(host, port);
      } catch (const zmq::error_t& e) {
        if (e.num() != EADDRINUSE) throw;
      }
    }
    if (endpoint_.empty()) throw std::runtime_error("bus proxy: no free pair of adjacent ports on " + host);
    return;
  }
  const BusEndpoints ep = split_bus_endpoint(bus);
  xsub_ = make_socket(*context_, zmq::socket_type::xsub, hwm, curve);
  xpub_ = make_socket(*context_, zmq::socket_type::xpub, hwm, curve);
  xsub_->bind(ep.publish);
  xpub_->bind(ep.subscribe);
  endpoint_ = bus;
}

void Proxy::run(const std::atomic<bool>& stop) {
  zmq::pollitem_t items[] = {{xsub_->handle(), 0, ZMQ_POLLIN, 0},
                             {xpub_->handle(), 0, ZMQ_POLLIN, 0}};
  while (!stop.load()) {
    try {
      if (zmq::poll(items, 2, std::chrono::milliseconds(100)) == 0) continue;
    } catch (const zmq::error_t& e) {
      if (e.num() == EINTR) continue;
      throw;
    }
    // Drain in batches: fewer polls under load.
    if (items[0].revents & ZMQ_POLLIN) {
      for (int i = 0; i < 256; ++i) {
        const auto bytes = forward(*xsub_, *xpub_);
        if (!bytes) break;
        stats_.messages.fetch_add(1, std::memory_order_relaxed);
        stats_.bytes.fetch_add(*bytes, std::memory_order_relaxed);
      }
    }
    if (items[1].revents & ZMQ_POLLIN) {
      for (int i = 0; i < 256; ++i) {
        if (!forward(*xpub_, *xsub_)) break;
        stats_.subscription_changes.fetch_add(1, std::memory_order_relaxed);
      }
    }
  }
}

}  // namespace chatsim::bus
