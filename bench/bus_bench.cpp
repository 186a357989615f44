#include "bench/bus_bench.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <functional>
#include <limits>
#include <thread>
#include <vector>

#include <zmq.hpp>

#include "common/bus/node.hpp"
#include "common/bus/proxy.hpp"
#include "common/util/clock.hpp"

namespace chatsim::bench {
namespace {

using namespace std::chrono_literals;

// A stream measurement: messages/s and bytes/s seen by the receiver.
struct Rate {
  double seconds = 0;
  long messages = 0;   // received
  double bytes = 0;
  long lost = 0;       // sent but never received
  static constexpr auto kIdleLimit = 2s;  // a receiver idle this long gives up on the rest
  double msgs_per_s() const { return messages / seconds; }
  double mb_per_s() const { return bytes / seconds / 1e6; }
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t i = std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5));
  return v[i];
}

// Flow control shared by both sides: the sender keeps at most `window` messages in flight,
// so neither path drops at its high-water mark and both are measured at their real pace.
// The sender blocks (futex, not a spin) so it leaves the cores to the path being measured.
struct Flow {
  std::atomic<long> received{0};
  void arrived(long n) {
    received.store(n, std::memory_order_release);
    received.notify_one();
  }
  // The receiver gave up: release the sender for good.
  void give_up() { arrived(std::numeric_limits<long>::max() / 2); }
  void wait_window(long sent, long window) {
    for (long r = received.load(std::memory_order_acquire); sent - r >= window;
         r = received.load(std::memory_order_acquire)) {
      received.wait(r, std::memory_order_acquire);
    }
  }
};

// ---- raw ZeroMQ ----------------------------------------------------------------------

struct RawPair {
  zmq::context_t ctx{1};
  zmq::socket_t pub{ctx, zmq::socket_type::pub};
  zmq::socket_t sub{ctx, zmq::socket_type::sub};
  explicit RawPair(const std::string& host) {
    for (auto* s : {&pub, &sub}) {
      s->set(zmq::sockopt::linger, 0);
      s->set(zmq::sockopt::sndhwm, 100000);
      s->set(zmq::sockopt::rcvhwm, 100000);
    }
    pub.bind("tcp://" + host + ":0");
    sub.connect(pub.get(zmq::sockopt::last_endpoint));
    sub.set(zmq::sockopt::subscribe, "");
    // Slow joiner: send until one arrives.
    for (;;) {
      zmq::message_t m(1);
      pub.send(m, zmq::send_flags::none);
      zmq::message_t r;
      if (sub.recv(r, zmq::recv_flags::dontwait)) break;
      std::this_thread::sleep_for(1ms);
    }
    zmq::message_t r;
    while (sub.recv(r, zmq::recv_flags::dontwait)) {
    }
  }
};

Rate raw_stream(const std::string& host, int size, int count, long window) {
  RawPair p(host);
  const std::vector<uint8_t> payload(size, 0x5a);
  Flow flow;
  Rate rate;
  std::thread receiver([&] {
    p.sub.set(zmq::sockopt::rcvtimeo, static_cast<int>(std::chrono::milliseconds(Rate::kIdleLimit).count()));
    zmq::message_t m;
    while (rate.messages < count && p.sub.recv(m, zmq::recv_flags::none)) {
      rate.bytes += m.size();
      flow.arrived(++rate.messages);
    }
    if (rate.messages < count) flow.give_up();
  });
  const double t0 = mono_s();
  for (long i = 0; i < count; ++i) {
    flow.wait_window(i, window);
    zmq::message_t m(size);
    std::memcpy(m.data(), payload.data(), size);  // the producer fills its message
    p.pub.send(m, zmq::send_flags::none);
  }
  receiver.join();
  rate.seconds = mono_s() - t0;
  rate.lost = count - rate.messages;
  return rate;
}

std::vector<double> raw_latency(const std::string& host, int size, int count) {
  RawPair ping(host), pong(host);
  std::atomic<bool> stop{false};
  std::thread echo([&] {
    zmq::message_t m;
    while (!stop.load()) {
      if (!ping.sub.recv(m, zmq::recv_flags::dontwait)) {
        std::this_thread::yield();
        continue;
      }
      pong.pub.send(m, zmq::send_flags::none);
    }
  });
  std::vector<double> rtt;
  const std::vector<uint8_t> payload(size, 0x5a);
  for (int i = 0; i < count + count / 10; ++i) {
    zmq::message_t m(payload.data(), payload.size());
    const double t0 = mono_s();
    ping.pub.send(m, zmq::send_flags::none);
    zmq::message_t r;
    (void)pong.sub.recv(r, zmq::recv_flags::none);
    if (i >= count / 10) rtt.push_back((mono_s() - t0) * 1e3);  // after warm-up
  }
  stop.store(true);
  echo.join();
  return rtt;
}

// ---- through the bus -----------------------------------------------------------------

struct BusHarness {
  std::shared_ptr<zmq::context_t> ctx = std::make_shared<zmq::context_t>(1);
  std::unique_ptr<bus::Proxy> proxy;
  std::atomic<bool> stop{false};
  std::thread forwarding;
  explicit BusHarness(const std::string& host) {
    proxy = std::make_unique<bus::Proxy>(ctx, "tcp://" + host + ":0", 100000);
    forwarding = std::thread([this] { proxy->run(stop); });
  }
  ~BusHarness() {
    stop.store(true);
    forwarding.join();
  }
  bus::NodeOptions options(const std::string& name) const {
    bus::NodeOptions o;
    o.name = name;
    o.kind = "bench";
    o.bus = proxy->endpoint();
    o.heartbeat_period = 0ms;
    o.send_hwm = o.receive_hwm = 100000;
    return o;
  }
};

void publish_payload(bus::Node& node, const std::string& topic, const std::vector<uint8_t>& payload) {
  flatbuffers::FlatBufferBuilder fbb(payload.size() + 256);
  uint8_t* dst = nullptr;
  fbb.ForceVectorAlignment(payload.size(), 1, 16);  // the schema's force_align: 16
  auto data = fbb.CreateUninitializedVector(payload.size(), 1, &dst);
  std::memcpy(dst, payload.data(), payload.size());  // the producer fills its message
  msgs::ImageBuilder ib(fbb);
  ib.add_data(data);
  ib.add_encoding(msgs::ImageEncoding::Jpeg);
  node.publish(topic, fbb, msgs::Payload::Image, ib.Finish().Union());
}

Rate bus_stream(const std::string& host, int size, int count, long window) {
  BusHarness h(host);
  Flow flow;
  Rate rate;
  std::atomic<bool> subscribed{false};
  std::thread receiver([&] {
    bus::Node sub(h.options("bench-sub"), h.ctx);
    long n = 0;
    sub.subscribe("/bench/stream", [&](const bus::Message& m) {
      rate.bytes += m.payload<msgs::Image>()->data()->size();
      flow.arrived(++n);
    });
    sub.start();
    subscribed.store(true);
    auto last = std::chrono::steady_clock::now();
    while (n < count && std::chrono::steady_clock::now() - last < Rate::kIdleLimit) {
      if (sub.spin_once(100ms) > 0) last = std::chrono::steady_clock::now();
    }
    rate.messages = n;
    if (n < count) flow.give_up();
  });
  while (!subscribed.load()) std::this_thread::sleep_for(1ms);
  bus::Node pub(h.options("bench-pub"), h.ctx);
  pub.start();
  // The publisher's own handshake proves its connection; subscriptions reached the proxy
  // before the subscriber's handshake completed, and were forwarded to us before our probe.
  const std::vector<uint8_t> payload(size, 0x5a);
  const double t0 = mono_s();
  for (long i = 0; i < count; ++i) {
    flow.wait_window(i, window);
    publish_payload(pub, "/bench/stream", payload);
  }
  receiver.join();
  rate.seconds = mono_s() - t0;
  rate.lost = count - rate.messages;
  return rate;
}

std::vector<double> bus_latency(const std::string& host, int size, int count) {
  BusHarness h(host);
  std::atomic<bool> stop{false}, ready{false};
  std::thread echo([&] {
    bus::Node node(h.options("bench-echo"), h.ctx);
    std::vector<uint8_t> payload(size, 0x5a);
    node.subscribe("/bench/ping", [&](const bus::Message&) { publish_payload(node, "/bench/pong", payload); });
    node.start();
    ready.store(true);
    while (!stop.load()) node.spin_once(10ms);
  });
  while (!ready.load()) std::this_thread::sleep_for(1ms);
  bus::Node node(h.options("bench-ping"), h.ctx);
  bool got = false;
  node.subscribe("/bench/pong", [&](const bus::Message&) { got = true; });
  node.start();
  const std::vector<uint8_t> payload(size, 0x5a);
  std::vector<double> rtt;
  for (int i = 0; i < count + count / 10; ++i) {
    got = false;
    const double t0 = mono_s();
    publish_payload(node, "/bench/ping", payload);
    while (!got) node.spin_once(100ms);
    if (i >= count / 10) rtt.push_back((mono_s() - t0) * 1e3);
  }
  stop.store(true);
  echo.join();
  return rtt;
}

Rate best(const std::function<Rate()>& f, int repeats) {
  Rate b;
  for (int i = 0; i < repeats; ++i) {
    const Rate r = f();
    if (b.seconds == 0 || r.seconds < b.seconds) b = r;
  }
  return b;
}

nlohmann::json rate_json(const Rate& r) {
  return {{"seconds", r.seconds}, {"messages", r.messages}, {"messages_per_s", r.msgs_per_s()},
          {"mb_per_s", r.mb_per_s()}, {"lost", r.lost}};
}

nlohmann::json latency_json(const std::vector<double>& rtt_ms) {
  return {{"samples", rtt_ms.size()},
          {"rtt_p50_ms", percentile(rtt_ms, 0.50)},
          {"rtt_p99_ms", percentile(rtt_ms, 0.99)},
          {"one_way_p50_ms", percentile(rtt_ms, 0.50) / 2},
          {"one_way_p99_ms", percentile(rtt_ms, 0.99) / 2}};
}

}  // namespace

nlohmann::json run_bus_bench(const BusBenchConfig& c) {
  const long small_window = 10000, image_window = 8;
  const Rate raw_small = best([&] { return raw_stream(c.host, c.small_size, c.small_count, small_window); }, c.repeats);
  const Rate bus_small = best([&] { return bus_stream(c.host, c.small_size, c.small_count, small_window); }, c.repeats);
  const Rate raw_image = best([&] { return raw_stream(c.host, c.image_size, c.image_count, image_window); }, c.repeats);
  const Rate bus_image = best([&] { return bus_stream(c.host, c.image_size, c.image_count, image_window); }, c.repeats);
  const auto raw_lat = raw_latency(c.host, c.small_size, c.latency_count);
  const auto bus_lat = bus_latency(c.host, c.small_size, c.latency_count);

  const double small_ratio = bus_small.msgs_per_s() / raw_small.msgs_per_s();
  const double image_ratio = bus_image.mb_per_s() / raw_image.mb_per_s();
  const double bus_p99 = percentile(bus_lat, 0.99);
  nlohmann::json report = {
      {"benchmark", "bus"},
      {"transport", "tcp loopback (" + c.host + ")"},
      {"cores", std::thread::hardware_concurrency()},
      {"config", {{"small_size", c.small_size}, {"small_count", c.small_count},
                  {"image_size", c.image_size}, {"image_count", c.image_count},
                  {"latency_count", c.latency_count}, {"repeats", c.repeats}}},
      {"raw_zmq", {{"small", rate_json(raw_small)}, {"image", rate_json(raw_image)},
                   {"latency", latency_json(raw_lat)}}},
      {"bus", {{"small", rate_json(bus_small)}, {"image", rate_json(bus_image)},
               {"latency", latency_json(bus_lat)}}},
      {"ratios", {{"small_throughput", small_ratio}, {"image_throughput", image_ratio},
                  {"latency_p99", bus_p99 / std::max(1e-9, percentile(raw_lat, 0.99))}}},
      {"targets", {{"small_throughput_min_ratio", 0.7}, {"image_throughput_min_ratio", 0.8},
                   {"latency_p99_max_ms", 1.0},
                   {"small_throughput_met", small_ratio >= 0.7},
                   {"image_throughput_met", image_ratio >= 0.8},
                   {"latency_p99_met", bus_p99 < 1.0}}},
  };
  return report;
}

}  // namespace chatsim::bench
