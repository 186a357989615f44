// CURVE on the bus: authorized nodes talk; a node without an authorized key can neither
// publish to nor read from the bus.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "common/bus/curve.hpp"
#include "common/bus/endpoint.hpp"
#include "common/bus/node.hpp"
#include "common/bus/proxy.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace {

struct SecureBus {
  fs::path keys = chatsim::scratch::dir() / ("chatsim-curve-" + std::to_string(::getpid()));
  std::shared_ptr<zmq::context_t> ctx = std::make_shared<zmq::context_t>(1);
  std::unique_ptr<bus::Proxy> proxy;
  std::atomic<bool> stop{false};
  std::thread thread;
  SecureBus() {
    fs::remove_all(keys);
    for (const char* n : {"bus", "alice", "bob"}) bus::write_curve_keys(keys, n, bus::generate_curve_keys());
    proxy = std::make_unique<bus::Proxy>(ctx, "tcp://127.0.0.1:0", 1000, bus::curve_server_from_dir(keys));
    thread = std::thread([this] { proxy->run(stop); });
  }
  ~SecureBus() {
    stop = true;
    thread.join();
  }
  bus::NodeOptions options(const std::string& name, const bus::CurveClient& curve) const {
    bus::NodeOptions o;
    o.name = name;
    o.kind = "test";
    o.bus = proxy->endpoint();
    o.heartbeat_period = 0ms;
    o.handshake_timeout = 1500ms;
    o.curve = curve;
    return o;
  }
};

}  // namespace

TEST(Curve, KeysRoundTripAndBadKeyFilesAreNamed) {
  const auto dir = chatsim::scratch::dir() / ("chatsim-curve-keys-" + std::to_string(::getpid()));
  const auto pair = bus::generate_curve_keys();
  bus::write_curve_keys(dir, "x", pair);
  EXPECT_EQ(bus::read_curve_key(dir / "x.pub"), pair.public_key);
  EXPECT_EQ(bus::read_curve_key(dir / "x.secret"), pair.secret_key);
  EXPECT_EQ(fs::status(dir / "x.secret").permissions() & fs::perms::group_read, fs::perms::none);
  std::ofstream(dir / "bad.pub") << "not a key\n";
  try {
    bus::read_curve_key(dir / "bad.pub");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.pub"), std::string::npos);
  }
}

TEST(Curve, AuthorizedNodesTalkAndStrangersCanNeitherPublishNorRead) {
  SecureBus b;
  bus::Node alice(b.options("alice", bus::curve_client_from_dir(b.keys, "alice")), b.ctx);
  bus::Node bob(b.options("bob", bus::curve_client_from_dir(b.keys, "bob")), b.ctx);
  int got = 0;
  bob.subscribe("/secret", [&](const bus::Message&) { ++got; });
  alice.start();
  bob.start();
  flatbuffers::FlatBufferBuilder fbb;
  auto probe = msgs::CreateProbe(fbb);
  ASSERT_EQ(alice.publish("/secret", fbb, msgs::Payload::Probe, probe.Union()), bus::PublishStatus::Sent);
  for (int i = 0; i < 50 && got == 0; ++i) bob.spin_once(20ms);
  EXPECT_EQ(got, 1);

  // A stranger with its own key pair (not in the folder), and one with no CURVE at all: both
  // fail the handshake, so they can neither publish nor read.
  bus::CurveClient stranger{bus::read_curve_key(b.keys / "bus.pub"), bus::generate_curve_keys()};
  EXPECT_THROW({ bus::Node mallory(b.options("mallory", stranger), b.ctx); mallory.start(); }, bus::BusError);
  EXPECT_THROW({ bus::Node plain(b.options("plain", {}), b.ctx); plain.start(); }, bus::BusError);

  // Raw sockets, to be sure nothing gets through either way.
  zmq::socket_t pub(*b.ctx, zmq::socket_type::pub);
  bus::apply_curve_client(pub, stranger);
  pub.set(zmq::sockopt::linger, 0);
  pub.connect(bus::split_bus_endpoint(b.proxy->endpoint()).publish);
  zmq::socket_t sub(*b.ctx, zmq::socket_type::sub);
  bus::apply_curve_client(sub, stranger);
  sub.set(zmq::sockopt::linger, 0);
  sub.set(zmq::sockopt::subscribe, "");
  sub.set(zmq::sockopt::rcvtimeo, 200);
  sub.connect(bus::split_bus_endpoint(b.proxy->endpoint()).subscribe);
  std::this_thread::sleep_for(300ms);
  for (int i = 0; i < 5; ++i) {
    pub.send(zmq::str_buffer("/secret"), zmq::send_flags::sndmore);
    pub.send(zmq::str_buffer("forged"), zmq::send_flags::none);
    ASSERT_EQ(alice.publish("/secret", fbb, msgs::Payload::Probe, msgs::CreateProbe(fbb).Union()), bus::PublishStatus::Sent);
  }
  for (int i = 0; i < 20; ++i) bob.spin_once(20ms);
  EXPECT_EQ(got, 6);  // alice's five, none forged (forged frames would also fail verification)
  EXPECT_EQ(bob.stats().invalid.load(), 0u);
  zmq::message_t m;
  EXPECT_FALSE(sub.recv(m));  // the stranger reads nothing
  EXPECT_GT(b.proxy->refused_connections(), 0u);
}
