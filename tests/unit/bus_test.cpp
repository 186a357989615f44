// The bus library through a real proxy on loopback (in-process, OS-chosen ports).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <thread>

#include "common/bus/endpoint.hpp"
#include "common/bus/errors.hpp"
#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "tests/support/bus_fixture.hpp"

using namespace chatsim;
using namespace std::chrono_literals;

namespace {

flatbuffers::Offset<void> probe(flatbuffers::FlatBufferBuilder& fbb, uint64_t n) {
  return msgs::CreateProbe(fbb, n).Union();
}

zmq::message_t envelope(const std::string& topic, const std::string& sender, uint64_t seq) {
  flatbuffers::FlatBufferBuilder fbb;
  auto h = msgs::CreateHeaderDirect(fbb, topic.c_str(), sender.c_str(), 7, seq, now_ns());
  msgs::FinishEnvelopeBuffer(fbb, msgs::CreateEnvelope(fbb, h, msgs::Payload::Probe, probe(fbb, seq)));
  return zmq::message_t(fbb.GetBufferPointer(), fbb.GetSize());
}

void send(zmq::socket_t& pub, const std::string& topic, zmq::message_t body) {
  zmq::message_t t(topic.data(), topic.size());
  pub.send(t, zmq::send_flags::sndmore);
  pub.send(body, zmq::send_flags::none);
}

using test_support::spin_until;

// A raw ZeroMQ publisher on the bus, for sending what a Node never would. It is ready once a
// warm-up message reached `receiver` (a started node): the proxy has passed it the subscriptions.
struct RawPublisher {
  zmq::socket_t pub;
  bool ready = false;
  RawPublisher(test_support::InProcessBus& b, bus::Node& receiver) : pub(*b.context(), zmq::socket_type::pub) {
    pub.set(zmq::sockopt::linger, 0);
    pub.connect(bus::split_bus_endpoint(b.endpoint()).publish);
    receiver.subscribe("/warm", [this](const bus::Message&) { ready = true; });
    uint64_t seq = 0;
    const auto end = std::chrono::steady_clock::now() + 5s;
    while (!ready && std::chrono::steady_clock::now() < end) {
      send(pub, "/warm", envelope("/warm", "warm", ++seq));
      receiver.spin_once(5ms);
    }
  }
};

}  // namespace

TEST(Bus, NoMessageLostAtStartUp) {
  test_support::InProcessBus b;
  bus::Node sub(b.options("sub"), b.context());
  int got = 0;
  sub.subscribe("/t", [&](const bus::Message& m) {
    EXPECT_EQ(m.type(), msgs::Payload::Probe);
    ++got;
  });
  sub.start();
  bus::Node pub(b.options("pub"), b.context());
  pub.start();
  for (int i = 0; i < 500; ++i) {  // right after start: the handshake makes this safe
    flatbuffers::FlatBufferBuilder fbb;
    ASSERT_EQ(pub.publish("/t", fbb, msgs::Payload::Probe, probe(fbb, i)), bus::PublishStatus::Sent);
  }
  EXPECT_TRUE(spin_until(sub, [&] { return got == 500; })) << got;
  EXPECT_EQ(sub.stats().gaps.load(), 0u);
  EXPECT_EQ(sub.stats().invalid.load(), 0u);
}

TEST(Bus, ExactTopicsDoNotMatchLongerOnes) {
  test_support::InProcessBus b;
  bus::Node node(b.options("n"), b.context());
  int exact = 0, prefixed = 0;
  node.subscribe("/a", [&](const bus::Message&) { ++exact; });
  node.subscribe_prefix("/a", [&](const bus::Message&) { ++prefixed; });
  node.start();
  for (const char* t : {"/a", "/ab", "/a/b"}) {
    flatbuffers::FlatBufferBuilder fbb;
    node.publish(t, fbb, msgs::Payload::Probe, probe(fbb, 1));
  }
  EXPECT_TRUE(spin_until(node, [&] { return prefixed == 3; }));
  EXPECT_EQ(exact, 1);
}

TEST(Bus, VerifierDropsCorruptAndMisframedMessages) {
  test_support::InProcessBus b;
  bus::Node sub(b.options("sub"), b.context());
  int good = 0;
  sub.subscribe_prefix("/t", [&](const bus::Message&) { ++good; });
  sub.start();
  RawPublisher raw(b, sub);
  ASSERT_TRUE(raw.ready);

  std::string garbage(200, '\xff');
  send(raw.pub, "/t", zmq::message_t(garbage.data(), garbage.size()));          // not a flatbuffer
  auto valid = envelope("/t", "x", 1);
  send(raw.pub, "/t", zmq::message_t(valid.data(), valid.size() / 2));         // truncated
  send(raw.pub, "/t2", envelope("/t", "x", 1));                                // topic mismatch
  zmq::message_t single("/t", 2);
  raw.pub.send(single, zmq::send_flags::none);                                 // one frame only
  zmq::message_t t3("/t", 2), a(valid.data(), valid.size()), extra("z", 1);    // three frames
  raw.pub.send(t3, zmq::send_flags::sndmore);
  raw.pub.send(a, zmq::send_flags::sndmore);
  raw.pub.send(extra, zmq::send_flags::none);
  auto bad_id = envelope("/t", "x", 2);
  std::memcpy(static_cast<char*>(bad_id.data()) + 4, "XXXX", 4);               // wrong file identifier
  send(raw.pub, "/t", std::move(bad_id));
  send(raw.pub, "/t", envelope("/t", "x", 3));                                 // finally a good one

  EXPECT_TRUE(spin_until(sub, [&] { return good == 1; }));
  EXPECT_TRUE(spin_until(sub, [&] { return sub.stats().invalid.load() == 6; })) << sub.stats().invalid.load();
  EXPECT_EQ(good, 1);
}

TEST(Bus, CountsSequenceGaps) {
  test_support::InProcessBus b;
  bus::Node sub(b.options("sub"), b.context());
  int got = 0;
  sub.subscribe("/t", [&](const bus::Message&) { ++got; });
  sub.start();
  RawPublisher raw(b, sub);
  ASSERT_TRUE(raw.ready);
  for (uint64_t seq : {1, 2, 5, 6, 10}) send(raw.pub, "/t", envelope("/t", "x", seq));
  EXPECT_TRUE(spin_until(sub, [&] { return got == 5; }));
  EXPECT_EQ(sub.stats().gaps.load(), 5u);  // 3, 4, 7, 8, 9
}

TEST(Bus, CallWithoutServerTimesOut) {
  test_support::InProcessBus b;
  bus::Node client(b.options("client"), b.context());
  client.start();
  flatbuffers::FlatBufferBuilder fbb;
  const double t0 = mono_s();
  auto r = client.call("/agent/nobody/request", fbb, msgs::Payload::Probe, probe(fbb, 1), 200ms);
  const double took = mono_s() - t0;
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error, msgs::ErrorCode::DeadlineExceeded);
  EXPECT_NE(r.error_message.find("/agent/nobody/request"), std::string::npos);
  EXPECT_GE(took, 0.19);
  EXPECT_LT(took, 1.0);
}

TEST(Bus, RequestResponseMatchesCorrelationIds) {
  test_support::InProcessBus b;
  std::atomic<bool> stop{false}, ready{false};
  std::thread server([&] {
    bus::Node node(b.options("server"), b.context());
    node.serve("/svc", [](const bus::Message& req, flatbuffers::FlatBufferBuilder& fbb) {
      const auto* p = req.payload<msgs::AgentRequest>();
      if (std::string(bus::view(p->action())) == "throw") throw std::runtime_error("boom");
      auto resp = msgs::CreateAgentResponseDirect(fbb, "svc", p->action()->c_str(), true, p->args_json()->c_str());
      return bus::Node::Reply{msgs::Payload::AgentResponse, resp.Union()};
    });
    node.start();
    ready.store(true);
    node.spin(stop);
  });
  while (!ready.load()) std::this_thread::sleep_for(1ms);
  bus::Node client(b.options("client"), b.context());
  client.start();
  for (int i = 0; i < 20; ++i) {
    flatbuffers::FlatBufferBuilder fbb;
    const std::string args = "{\"i\":" + std::to_string(i) + "}";
    auto req = msgs::CreateAgentRequestDirect(fbb, "svc", "echo", "", args.c_str());
    auto r = client.call("/svc", fbb, msgs::Payload::AgentRequest, req.Union(), 2s);
    ASSERT_TRUE(r.ok()) << r.error_message;
    EXPECT_EQ(bus::view(r.response->payload<msgs::AgentResponse>()->result_json()), args);
  }
  flatbuffers::FlatBufferBuilder fbb;
  auto req = msgs::CreateAgentRequestDirect(fbb, "svc", "throw");
  auto r = client.call("/svc", fbb, msgs::Payload::AgentRequest, req.Union(), 2s);
  ASSERT_TRUE(r.ok());
  const auto* err = r.response->payload<msgs::Error>();
  ASSERT_NE(err, nullptr);
  EXPECT_EQ(err->code(), msgs::ErrorCode::Internal);
  EXPECT_EQ(bus::view(err->cause()), "boom");
  EXPECT_EQ(bus::view(err->node()), "server");
  stop.store(true);
  server.join();
}

TEST(Bus, RequestsPastTheirDeadlineAreDroppedAndLateRepliesCounted) {
  test_support::InProcessBus b;
  bus::Node server(b.options("server"), b.context());
  int served = 0;
  server.serve("/svc", [&](const bus::Message&, flatbuffers::FlatBufferBuilder& fbb) {
    ++served;
    return bus::Node::Reply{msgs::Payload::Probe, probe(fbb, 0)};
  });
  server.start();
  bus::Node client(b.options("client"), b.context());
  client.start();
  flatbuffers::FlatBufferBuilder fbb;
  // The server is not spinning: the call times out, and the request expires unserved.
  auto r = client.call("/svc", fbb, msgs::Payload::Probe, probe(fbb, 1), 100ms);
  EXPECT_EQ(r.error, msgs::ErrorCode::DeadlineExceeded);
  EXPECT_TRUE(spin_until(server, [&] { return server.stats().expired.load() == 1; }));
  EXPECT_EQ(served, 0);
}

TEST(Bus, LargeImagesArriveIntactAndAligned) {
  test_support::InProcessBus b;
  bus::Node sub(b.options("sub"), b.context());
  const uint32_t w = 1920, h = 1280;
  bool ok = false;
  sub.subscribe("/img", [&](const bus::Message& m) {
    const auto* img = m.payload<msgs::Image>();
    ASSERT_NE(img, nullptr);
    ASSERT_EQ(img->data()->size(), w * h * 3);
    // ZeroMQ's receive buffers are 8-byte aligned: enough to read floats and doubles in place.
    EXPECT_EQ(reinterpret_cast<uintptr_t>(img->data()->data()) % 8, 0u);
    const uint8_t* d = img->data()->data();
    for (size_t i = 0; i < img->data()->size(); i += 9973) ASSERT_EQ(d[i], static_cast<uint8_t>(i * 31));
    ok = true;
  });
  sub.start();
  bus::Node pub(b.options("pub"), b.context());
  pub.start();
  flatbuffers::FlatBufferBuilder fbb(w * h * 3 + 1024);
  uint8_t* dst = nullptr;
  fbb.ForceVectorAlignment(w * h * 3, 1, 16);
  auto data = fbb.CreateUninitializedVector(w * h * 3, 1, &dst);
  for (size_t i = 0; i < size_t{w} * h * 3; ++i) dst[i] = static_cast<uint8_t>(i * 31);
  auto img = msgs::CreateImage(fbb, fbb.CreateString("CAM_FRONT"), 0, 0.0, w, h, w * 3,
                               msgs::ImageEncoding::Rgb8, data);
  pub.publish("/img", fbb, msgs::Payload::Image, img.Union());
  EXPECT_TRUE(spin_until(sub, [&] { return ok; }));
}

TEST(Bus, NodesBeatWithTheirNameAndPid) {
  test_support::InProcessBus b;
  bus::Node watcher(b.options("watcher"), b.context());
  std::string seen;
  int pid = 0;
  watcher.subscribe(std::string(bus::topics::kHeartbeat), [&](const bus::Message& m) {
    const auto* hb = m.payload<msgs::Heartbeat>();
    if (bus::view(hb->node()) != "beater") return;
    seen = bus::view(hb->node());
    pid = hb->pid();
  });
  watcher.start();
  bus::Node beater(b.options("beater", 50), b.context());
  beater.start();
  EXPECT_TRUE(spin_until(watcher, [&] { return !seen.empty(); }, 3s));
  EXPECT_EQ(pid, getpid());
}

TEST(Bus, UnreachableProxyIsAClearError) {
  auto ctx = std::make_shared<zmq::context_t>(1);
  bus::NodeOptions o;
  o.name = "lonely";
  o.kind = "test";
  o.bus = "tcp://127.0.0.1:1";
  o.handshake_timeout = 300ms;
  bus::Node node(o, ctx);
  try {
    node.start();
    FAIL();
  } catch (const bus::BusError& e) {
    EXPECT_NE(std::string(e.what()).find("tcp://127.0.0.1:1"), std::string::npos) << e.what();
  }
}
