#include "common/bus/node.hpp"

#include <algorithm>

#include <unistd.h>

#include <cerrno>
#include <random>

#include <spdlog/spdlog.h>

#include "common/bus/endpoint.hpp"
#include "common/bus/errors.hpp"
#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"

namespace chatsim::bus {
namespace {

uint64_t random_instance() {
  std::random_device rd;
  const uint64_t v = (uint64_t{rd()} << 32) ^ rd() ^ static_cast<uint64_t>(now_ns());
  return v == 0 ? 1 : v;
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

// Direct-link sockets: loopback only, where direct links are used only without encryption.
void configure_unencrypted(zmq::socket_t& s, const NodeOptions& o) {
  s.set(zmq::sockopt::linger, o.linger_ms);
  s.set(zmq::sockopt::sndhwm, o.send_hwm);
  s.set(zmq::sockopt::rcvhwm, o.receive_hwm);
}

void configure(zmq::socket_t& s, const NodeOptions& o) {
  configure_unencrypted(s, o);
  apply_curve_client(s, o.curve);
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// Zero-copy hand-over of a finished builder's buffer to ZeroMQ.
zmq::message_t take_buffer(flatbuffers::FlatBufferBuilder& fbb) {
  auto* detached = new flatbuffers::DetachedBuffer(fbb.Release());
  return zmq::message_t(
      detached->data(), detached->size(),
      [](void*, void* hint) { delete static_cast<flatbuffers::DetachedBuffer*>(hint); }, detached);
}

flatbuffers::Offset<flatbuffers::String> optional_string(flatbuffers::FlatBufferBuilder& fbb,
                                                         const std::string& s) {
  return s.empty() ? flatbuffers::Offset<flatbuffers::String>() : fbb.CreateString(s);
}

// Finishes payload in fbb as an Envelope with its header; the buffer becomes the message body
// without a copy.
zmq::message_t envelope_body(std::string_view topic, std::string_view sender, uint64_t instance,
                             uint64_t seq, flatbuffers::FlatBufferBuilder& fbb, msgs::Payload type,
                             flatbuffers::Offset<void> payload, const PublishOptions& options) {
  auto header = msgs::CreateHeader(fbb, fbb.CreateString(topic), fbb.CreateString(sender), instance,
                                   seq, now_ns(), optional_string(fbb, options.correlation_id),
                                   optional_string(fbb, options.reply_to), options.deadline_ns,
                                   optional_string(fbb, options.reply_endpoint));
  msgs::FinishEnvelopeBuffer(fbb, msgs::CreateEnvelope(fbb, header, type, payload));
  return take_buffer(fbb);
}

// Sends [topic, body]; false (nothing sent) when the socket would block.
bool send_frames(zmq::socket_t& socket, std::string_view topic, zmq::message_t& body) {
  zmq::message_t topic_frame(topic.data(), topic.size());
  if (!socket.send(topic_frame, zmq::send_flags::sndmore | zmq::send_flags::dontwait)) return false;
  // Once the first frame is queued the second always is: ZeroMQ queues multipart atomically.
  socket.send(body, zmq::send_flags::none);
  return true;
}

// Shared by publish() and the heartbeat thread (each with its own socket).
bool send_envelope(zmq::socket_t& socket, std::string_view topic, std::string_view sender,
                   uint64_t instance, uint64_t seq, flatbuffers::FlatBufferBuilder& fbb,
                   msgs::Payload type, flatbuffers::Offset<void> payload,
                   const PublishOptions& options) {
  zmq::message_t body = envelope_body(topic, sender, instance, seq, fbb, type, payload, options);
  return send_frames(socket, topic, body);
}

// Direct links only where every peer can reach a loopback inbox and nothing is encrypted.
bool direct_links_possible(const NodeOptions& o) {
  if (!o.direct_links || o.curve.enabled()) return false;
  const std::string pub = split_bus_endpoint(o.bus).publish;
  return starts_with(pub, "tcp://127.") || starts_with(pub, "tcp://localhost:");
}

constexpr size_t kMaxOutboxes = 8;

}  // namespace

Node::Node(NodeOptions options, std::shared_ptr<zmq::context_t> context)
    : options_(std::move(options)),
      context_(context ? std::move(context) : std::make_shared<zmq::context_t>(1)),
      instance_(random_instance()) {
  if (options_.name.empty()) throw std::invalid_argument("bus node: empty --name");
  if (options_.name.find('/') != std::string::npos) {
    throw std::invalid_argument("bus node name '" + options_.name + "' must not contain '/'");
  }
  if (options_.kind.empty()) options_.kind = options_.name;
  reply_topic_ = topics::reply(options_.name, instance_);
}

Node::~Node() { shutdown(); }

void Node::start() {
  if (started_) return;
  const BusEndpoints ep = split_bus_endpoint(options_.bus);
  // XPUB, used as a PUB that can also read which prefixes are subscribed (see tapped()).
  pub_ = std::make_unique<zmq::socket_t>(*context_, zmq::socket_type::xpub);
  sub_ = std::make_unique<zmq::socket_t>(*context_, zmq::socket_type::sub);
  configure(*pub_, options_);
  configure(*sub_, options_);
  pub_->connect(ep.publish);
  sub_->connect(ep.subscribe);
  start_mono_s_ = mono_s();
  started_ = true;
  if (direct_links_possible(options_)) open_inbox();
  // With an inbox, responses arrive there; the proxy would only add a second copy.
  if (inbox_endpoint_.empty()) sub_->set(zmq::sockopt::subscribe, reply_topic_);
  for (const auto& s : subscriptions_)
    if (!s.direct_only) sub_->set(zmq::sockopt::subscribe, s.topic);
  sync();
  if (options_.heartbeat_period.count() > 0) {
    heartbeat_thread_ = std::thread([this] { heartbeat_loop(); });
  }
  state_.store(msgs::NodeState::Ready);
}

void Node::shutdown() {
  if (shut_down_) return;
  shut_down_ = true;
  state_.store(msgs::NodeState::Stopping);
  heartbeat_stop_.store(true);
  if (heartbeat_thread_.joinable()) heartbeat_thread_.join();
  if (sub_) sub_->close();
  if (pub_) pub_->close();
  if (inbox_) inbox_->close();
  for (auto& [endpoint, socket] : outboxes_) socket->close();
}

void Node::open_inbox() {
  inbox_ = std::make_unique<zmq::socket_t>(*context_, zmq::socket_type::pull);
  configure_unencrypted(*inbox_, options_);
  inbox_->bind("tcp://127.0.0.1:0");
  inbox_endpoint_ = inbox_->get(zmq::sockopt::last_endpoint);
}

zmq::socket_t& Node::outbox(const std::string& inbox) {
  auto it = std::find_if(outboxes_.begin(), outboxes_.end(), [&](const auto& o) { return o.first == inbox; });
  if (it != outboxes_.end()) {
    std::rotate(it, it + 1, outboxes_.end());  // most recently used last
    return *outboxes_.back().second;
  }
  if (outboxes_.size() >= kMaxOutboxes) outboxes_.erase(outboxes_.begin());  // closes it
  auto socket = std::make_unique<zmq::socket_t>(*context_, zmq::socket_type::push);
  configure_unencrypted(*socket, options_);
  socket->connect(inbox);  // queues from now on, before the connection completes
  outboxes_.emplace_back(inbox, std::move(socket));
  return *outboxes_.back().second;
}

PublishStatus Node::send_direct(const std::string& inbox, std::string_view topic,
                                flatbuffers::FlatBufferBuilder& fbb, msgs::Payload type,
                                flatbuffers::Offset<void> payload, const PublishOptions& options) {
  if (!started_ || shut_down_) throw BusError("node '" + options_.name + "' is not running");
  zmq::message_t body = envelope_body(topic, options_.name, instance_, next_seq(topic), fbb, type,
                                      payload, options);
  zmq::message_t tap_copy;
  tap_copy.copy(body);  // shares the bytes: no copy of a large body
  if (!outbox(inbox).send(body, zmq::send_flags::dontwait)) return PublishStatus::WouldBlock;
  if (tapped(topic)) (void)send_frames(*pub_, topic, tap_copy);
  stats_.sent.fetch_add(1, std::memory_order_relaxed);
  return PublishStatus::Sent;
}

bool Node::tapped(std::string_view topic) {
  read_subscription_changes();
  return std::any_of(subscribed_.begin(), subscribed_.end(),
                     [&](const auto& s) { return starts_with(topic, s.first); });
}

void Node::read_subscription_changes() {
  // What the proxy forwards to this publisher: 1 or 0, then the prefix. Read often, as XPUB
  // keeps them until read.
  zmq::message_t change;
  while (pub_->recv(change, zmq::recv_flags::dontwait)) {
    const std::string_view bytes = change.to_string_view();
    if (bytes.empty()) continue;
    const std::string prefix(bytes.substr(1));
    if (bytes[0] == 1) {
      ++subscribed_[prefix];
    } else if (auto it = subscribed_.find(prefix); it != subscribed_.end() && --it->second <= 0) {
      subscribed_.erase(it);
    }
  }
}

void Node::subscribe_direct(const std::string& topic, Handler handler) {
  subscriptions_.push_back({topic, false, std::move(handler), true});
}

void Node::subscribe(const std::string& topic, Handler handler) {
  add_subscription({topic, false, std::move(handler)});
}

void Node::subscribe_prefix(const std::string& prefix, Handler handler) {
  add_subscription({prefix, true, std::move(handler)});
}

void Node::add_subscription(Subscription sub) {
  const bool known = std::any_of(subscriptions_.begin(), subscriptions_.end(), [&](const Subscription& s) {
    return s.topic == sub.topic && !s.direct_only;
  });
  subscriptions_.push_back(std::move(sub));
  if (started_ && !known) {
    sub_->set(zmq::sockopt::subscribe, subscriptions_.back().topic);
    sync();
  }
}

uint64_t Node::next_seq(std::string_view topic) {
  auto it = seqs_.find(topic);
  if (it == seqs_.end()) it = seqs_.emplace(std::string(topic), 0).first;
  return ++it->second;
}

PublishStatus Node::republish(std::string_view topic, std::string_view bytes) {
  if (!started_ || shut_down_) throw BusError("node '" + options_.name + "' is not running");
  zmq::message_t topic_frame(topic.data(), topic.size());
  zmq::message_t body(bytes.data(), bytes.size());
  if (!pub_->send(topic_frame, zmq::send_flags::sndmore | zmq::send_flags::dontwait)) return PublishStatus::WouldBlock;
  pub_->send(body, zmq::send_flags::none);
  stats_.sent.fetch_add(1, std::memory_order_relaxed);
  return PublishStatus::Sent;
}

PublishStatus Node::publish(std::string_view topic, flatbuffers::FlatBufferBuilder& fbb,
                            msgs::Payload type, flatbuffers::Offset<void> payload,
                            const PublishOptions& options) {
  if (!started_ || shut_down_) throw BusError("node '" + options_.name + "' is not running");
  read_subscription_changes();
  if (!send_envelope(*pub_, topic, options_.name, instance_, next_seq(topic), fbb, type, payload,
                     options)) {
    return PublishStatus::WouldBlock;
  }
  stats_.sent.fetch_add(1, std::memory_order_relaxed);
  return PublishStatus::Sent;
}

std::optional<Message> Node::receive(std::chrono::milliseconds timeout) {
  // Take what already waits before polling: a poll per message would cost more than the
  // message under load.
  zmq::socket_t* sockets[2] = {sub_.get(), inbox_.get()};
  const size_t count = inbox_ ? 2 : 1;
  inbox_first_ = !inbox_first_ && inbox_;
  if (inbox_first_) std::swap(sockets[0], sockets[1]);
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t i = 0; i < count; ++i) {
      bool took = false;
      auto m = take_from(*sockets[i], took);
      if (took) return m;  // nullopt here: it was invalid, dropped and counted
    }
    if (pass == 1 || timeout.count() <= 0) break;
    read_subscription_changes();  // idle: a good moment
    zmq::pollitem_t items[2] = {{sockets[0]->handle(), 0, ZMQ_POLLIN, 0},
                                {count == 2 ? sockets[1]->handle() : nullptr, 0, ZMQ_POLLIN, 0}};
    try {
      if (zmq::poll(items, count, timeout) == 0) return std::nullopt;
    } catch (const zmq::error_t& e) {
      if (e.num() == EINTR) return std::nullopt;  // a signal: let the caller look at its stop flag
      throw;
    }
  }
  return std::nullopt;
}

std::optional<Message> Node::take_from(zmq::socket_t& socket, bool& took) {
  // Through the proxy: [topic, envelope] (subscribers filter on the topic frame). In the inbox:
  // [envelope] alone, since nothing there filters: one frame less per message.
  const bool topic_framed = &socket != inbox_.get();
  zmq::message_t first;
  if (!socket.recv(first, zmq::recv_flags::dontwait)) return std::nullopt;
  took = true;
  bool well_framed = true;
  zmq::message_t topic_frame, body;
  if (topic_framed) {
    topic_frame = std::move(first);
    well_framed = topic_frame.more();
    if (well_framed) (void)socket.recv(body, zmq::recv_flags::none);
  } else {
    body = std::move(first);
  }
  for (bool more = body.more(); more;) {  // extra frames: drain and reject the whole message
    well_framed = false;
    zmq::message_t extra;
    (void)socket.recv(extra, zmq::recv_flags::none);
    more = extra.more();
  }
  stats_.received.fetch_add(1, std::memory_order_relaxed);
  Message message(std::move(body));
  const bool valid = well_framed && message.verify() &&
                     (!topic_framed || message.topic() == topic_frame.to_string_view());
  if (!valid) {
    const uint64_t n = stats_.invalid.fetch_add(1, std::memory_order_relaxed) + 1;
    if (n <= 5 || n % 1000 == 0) {
      spdlog::warn("[{}] dropped an invalid message {} ({} bytes; {} invalid so far)", options_.name,
                   topic_framed ? "on '" + topic_frame.to_string() + "'" : std::string("in the inbox"),
                   message.size(), n);
    }
    return std::nullopt;
  }
  const auto& h = message.header();
  const auto obs = tracker_.observe(message.sender(), h.sender_instance(), message.topic(), h.seq());
  if (obs.missing > 0) {
    stats_.gaps.fetch_add(obs.missing, std::memory_order_relaxed);
    spdlog::warn("[{}] {} message(s) lost on '{}' from '{}' (sequence gap)", options_.name,
                 obs.missing, message.topic(), message.sender());
  }
  if (obs.duplicate) stats_.duplicates.fetch_add(1, std::memory_order_relaxed);
  return message;
}

void Node::dispatch(const Message& message) {
  const std::string_view topic = message.topic();
  if (topic == reply_topic_) {
    stats_.late_replies.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  for (size_t i = 0; i < subscriptions_.size(); ++i) {
    const Subscription& s = subscriptions_[i];
    const bool match = s.prefix ? starts_with(topic, s.topic) : topic == s.topic;
    if (!match) continue;
    try {
      s.handler(message);
    } catch (const std::exception& e) {
      spdlog::error("[{}] handler for '{}' failed: {}", options_.name, topic, e.what());
    }
  }
}

size_t Node::spin_once(std::chrono::milliseconds timeout) {
  size_t n = 0;
  while (!queued_.empty()) {
    Message m = std::move(queued_.front());
    queued_.pop_front();
    dispatch(m);
    ++n;
  }
  if (n > 0) timeout = 0ms;
  for (auto m = receive(timeout); m; m = receive(0ms)) {
    dispatch(*m);
    if (++n >= 1000) break;  // let the caller look at its stop flag now and then
  }
  return n;
}

void Node::spin(const std::atomic<bool>& stop) {
  while (!stop.load()) spin_once(100ms);
}

void Node::probe_until_echo(const std::string& probe_topic) {
  bool echoed = false;
  sub_->set(zmq::sockopt::subscribe, probe_topic);
  const auto deadline = std::chrono::steady_clock::now() + options_.handshake_timeout;
  while (!echoed && std::chrono::steady_clock::now() < deadline) {
    flatbuffers::FlatBufferBuilder fbb(128);
    publish(probe_topic, fbb, msgs::Payload::Probe, msgs::CreateProbe(fbb, probe_counter_).Union());
    const auto until = std::chrono::steady_clock::now() + 20ms;
    while (std::chrono::steady_clock::now() < until) {
      auto m = receive(5ms);
      if (!m) continue;
      if (m->topic() == probe_topic) {
        echoed = true;
        break;
      }
      queued_.push_back(std::move(*m));
    }
  }
  sub_->set(zmq::sockopt::unsubscribe, probe_topic);
  if (!echoed) {
    throw BusError("node '" + options_.name + "': no answer from the bus proxy at " +
                   options_.bus + " within " + std::to_string(options_.handshake_timeout.count()) +
                   " ms (is chatsim-bus running there?)");
  }
}

void Node::sync() {
  // A fresh probe topic each time: its subscription travels behind every earlier one on the
  // same connection, so its echo proves the proxy has processed them all.
  probe_until_echo(topics::probe(options_.name, instance_, ++probe_counter_));
}

void Node::heartbeat_loop() {
  zmq::socket_t pub(*context_, zmq::socket_type::pub);
  configure(pub, options_);
  pub.connect(split_bus_endpoint(options_.bus).publish);
  const std::string host = host_name();
  uint64_t seq = 0;
  auto beat = [&](msgs::NodeState state) {
    flatbuffers::FlatBufferBuilder fbb(256);
    auto hb = msgs::CreateHeartbeat(
        fbb, fbb.CreateString(options_.name), fbb.CreateString(options_.kind),
        static_cast<int32_t>(getpid()), fbb.CreateString(host), state, mono_s() - start_mono_s_,
        static_cast<uint32_t>(options_.heartbeat_period.count()), stats_.received.load(),
        stats_.invalid.load(), stats_.gaps.load());
    send_envelope(pub, topics::kHeartbeat, options_.name, instance_, ++seq, fbb,
                  msgs::Payload::Heartbeat, hb.Union(), {});
  };
  // The first few beats come quickly: this socket is new and the first may be lost while it
  // connects, and launchers wait for a beat before starting the next process.
  auto next = std::chrono::steady_clock::now();
  int beats = 0;
  while (!heartbeat_stop_.load()) {
    if (std::chrono::steady_clock::now() >= next) {
      beat(state_.load());
      next += ++beats < 5 ? std::min<std::chrono::milliseconds>(options_.heartbeat_period, 25ms)
                          : options_.heartbeat_period;
    }
    std::this_thread::sleep_for(std::min<std::chrono::milliseconds>(options_.heartbeat_period, 20ms));
  }
  beat(msgs::NodeState::Stopping);  // a clean goodbye, so monitors do not report a failure
  pub.close();
}

}  // namespace chatsim::bus
