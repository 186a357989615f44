// Direct links: responses and streams go to the receiver's inbox without the proxy's two
// hops, lose nothing, still reach taps, and switch off where they cannot work.
#include <gtest/gtest.h>

#include <thread>

#include "common/bus/topics.hpp"
#include "tests/support/bus_fixture.hpp"

using namespace chatsim;
using namespace std::chrono_literals;

namespace {

using test_support::spin_until;

flatbuffers::Offset<void> blob(flatbuffers::FlatBufferBuilder& fbb, size_t size) {
  uint8_t* dst = nullptr;
  fbb.ForceVectorAlignment(size, 1, 16);
  auto data = fbb.CreateUninitializedVector(size, 1, &dst);
  for (size_t i = 0; i < size; ++i) dst[i] = static_cast<uint8_t>(i * 7);
  return msgs::CreateImage(fbb, 0, 0, 0.0, 0, 0, 0, msgs::ImageEncoding::Jpeg, data).Union();
}

// A server answering every request on /svc with a `size`-byte image, in its own thread.
struct BlobServer {
  std::atomic<bool> stop{false}, ready{false};
  std::thread thread;
  BlobServer(test_support::InProcessBus& b, size_t size) {
    thread = std::thread([this, &b, size] {
      bus::Node node(b.options("server"), b.context());
      node.serve("/svc", [size](const bus::Message&, flatbuffers::FlatBufferBuilder& fbb) {
        return bus::Node::Reply{msgs::Payload::Image, blob(fbb, size)};
      });
      node.start();
      ready.store(true);
      node.spin(stop);
    });
    while (!ready.load()) std::this_thread::sleep_for(1ms);
  }
  ~BlobServer() {
    stop.store(true);
    thread.join();
  }
};

bus::CallResult call_svc(bus::Node& client) {
  flatbuffers::FlatBufferBuilder fbb;
  return client.call("/svc", fbb, msgs::Payload::Probe, msgs::CreateProbe(fbb, 1).Union(), 5s);
}

}  // namespace

TEST(DirectLinks, ResponsesSkipTheProxy) {
  test_support::InProcessBus b;
  const size_t size = 4 << 20;
  BlobServer server(b, size);
  bus::Node client(b.options("client"), b.context());
  client.start();
  ASSERT_EQ(client.inbox().rfind("tcp://127.0.0.1:", 0), 0u) << client.inbox();
  for (int i = 0; i < 3; ++i) {
    const auto r = call_svc(client);
    ASSERT_TRUE(r.ok()) << r.error_message;
    ASSERT_EQ(r.response->payload<msgs::Image>()->data()->size(), size);
    EXPECT_EQ(r.response->payload<msgs::Image>()->data()->Get(size - 1), static_cast<uint8_t>((size - 1) * 7));
  }
  // Requests and handshakes crossed the proxy; the 12 MB of answers did not.
  EXPECT_LT(b.proxy_stats().bytes.load(), 100'000u);
  EXPECT_EQ(client.stats().late_replies.load(), 0u);
  EXPECT_EQ(client.stats().duplicates.load(), 0u);
}

TEST(DirectLinks, TapsStillSeeDirectResponses) {
  test_support::InProcessBus b;
  BlobServer server(b, 1000);
  bus::Node tap(b.options("tap"), b.context());
  int tapped = 0;
  tap.subscribe_prefix("/reply/", [&](const bus::Message& m) {
    if (m.type() == msgs::Payload::Image) ++tapped;
  });
  tap.start();
  bus::Node client(b.options("client"), b.context());
  client.start();
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(call_svc(client).ok());
  EXPECT_TRUE(spin_until(tap, [&] { return tapped == 5; })) << tapped;
  EXPECT_EQ(client.stats().late_replies.load(), 0u);  // the tap copy did not reach the client
}

TEST(DirectLinks, StreamToAnInboxLosesNothingFromTheFirstMessage) {
  test_support::InProcessBus b;
  bus::Node sub(b.options("sub"), b.context());
  std::vector<uint64_t> seqs;
  sub.subscribe_direct("/stream", [&](const bus::Message& m) { seqs.push_back(m.header().seq()); });
  sub.start();
  bus::Node pub(b.options("pub"), b.context());
  pub.start();
  const int n = 2000;
  for (int i = 0; i < n; ++i) {  // at once: the outbox queues until its connection is up
    flatbuffers::FlatBufferBuilder fbb;
    ASSERT_EQ(pub.send_direct(sub.inbox(), "/stream", fbb, msgs::Payload::Image, blob(fbb, 1024)),
              bus::PublishStatus::Sent);
  }
  EXPECT_TRUE(spin_until(sub, [&] { return seqs.size() == n; })) << seqs.size();
  for (size_t i = 0; i < seqs.size(); ++i) ASSERT_EQ(seqs[i], i + 1);
  EXPECT_EQ(sub.stats().gaps.load(), 0u);
}

TEST(DirectLinks, CorruptInboxMessagesAreDroppedAndCounted) {
  test_support::InProcessBus b;
  bus::Node sub(b.options("sub"), b.context());
  int got = 0;
  sub.subscribe_direct("/stream", [&](const bus::Message&) { ++got; });
  sub.start();
  zmq::socket_t push(*b.context(), zmq::socket_type::push);
  push.set(zmq::sockopt::linger, 0);
  push.connect(sub.inbox());
  const std::string topic = "/stream", junk = "not a flatbuffer at all";
  push.send(zmq::buffer(junk), zmq::send_flags::none);  // fails verification
  push.send(zmq::buffer(topic), zmq::send_flags::sndmore);  // the proxy's framing: not an inbox's
  push.send(zmq::buffer(junk), zmq::send_flags::none);
  bus::Node pub(b.options("pub"), b.context());
  pub.start();
  flatbuffers::FlatBufferBuilder fbb;
  pub.send_direct(sub.inbox(), "/stream", fbb, msgs::Payload::Image, blob(fbb, 16));
  EXPECT_TRUE(spin_until(sub, [&] { return got == 1 && sub.stats().invalid.load() == 2; }));
}

TEST(DirectLinks, SwitchedOffEverythingGoesThroughTheProxy) {
  test_support::InProcessBus b;
  BlobServer server(b, 1000);
  auto o = b.options("client");
  o.direct_links = false;
  bus::Node client(o, b.context());
  client.start();
  EXPECT_TRUE(client.inbox().empty());
  ASSERT_TRUE(call_svc(client).ok());
  // The answer crossed the proxy (whose counter may lag its forwarding by a moment).
  const auto end = std::chrono::steady_clock::now() + 2s;
  while (b.proxy_stats().bytes.load() <= 1000u && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(1ms);
  EXPECT_GT(b.proxy_stats().bytes.load(), 1000u);
}
