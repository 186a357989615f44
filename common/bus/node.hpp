#pragma once
// A bus node: one PUB and one SUB socket connected to the proxy, a heartbeat thread, and
// request/response with correlation ids and deadlines. Single-threaded API: call everything
// but stats() from the thread that created the node.
//
// Direct links (as ROS nodes talk peer to peer once the master introduced them): on a
// loopback, unencrypted bus a node binds an inbox (PULL) and its requests carry the inbox's
// endpoint, so responses skip the proxy's two hops; send_direct() streams to an inbox the
// same way. A copy goes through the proxy too when a tap or recorder subscribes to the
// topic. Elsewhere everything goes through the proxy.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <flatbuffers/flatbuffers.h>
#include <zmq.hpp>

#include "common/bus/curve.hpp"
#include "common/bus/message.hpp"
#include "common/bus/sequence_tracker.hpp"

namespace chatsim::bus {

using namespace std::chrono_literals;

struct NodeOptions {
  std::string name;                 // unique on the bus, e.g. "motion"
  std::string kind;                 // what it is, e.g. "motion", "mock", "cli"
  std::string bus;                  // bus endpoint (see endpoint.hpp)
  std::chrono::milliseconds heartbeat_period = 500ms;  // 0: no heartbeats
  std::chrono::milliseconds handshake_timeout = 5s;
  int linger_ms = 200;              // finite linger: never hang on exit
  int send_hwm = 10000;
  int receive_hwm = 10000;
  CurveClient curve;                // empty: no encryption or authentication
  bool direct_links = true;         // used only where possible (see above)
};

struct NodeStats {
  std::atomic<uint64_t> sent{0};
  std::atomic<uint64_t> received{0};
  std::atomic<uint64_t> invalid{0};      // failed verification or framing: dropped
  std::atomic<uint64_t> gaps{0};         // missing sequence numbers
  std::atomic<uint64_t> duplicates{0};
  std::atomic<uint64_t> expired{0};      // requests received after their deadline
  std::atomic<uint64_t> late_replies{0}; // responses for calls that already timed out
};

enum class PublishStatus { Sent, WouldBlock };

struct PublishOptions {
  std::string correlation_id;
  std::string reply_to;
  int64_t deadline_ns = 0;
  std::string reply_endpoint;       // the requester's inbox (direct links)
};

// What a request turned into: a response, or an error saying why there is none.
struct CallResult {
  std::optional<Message> response;
  msgs::ErrorCode error = msgs::ErrorCode::None;
  std::string error_message;
  bool ok() const { return response.has_value(); }
};

class BusError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Node {
 public:
  using Handler = std::function<void(const Message&)>;

  explicit Node(NodeOptions options, std::shared_ptr<zmq::context_t> context = nullptr);
  ~Node();
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  // Connects and completes the slow-joiner handshake: returns once a probe published by this
  // node came back through the proxy. Throws BusError naming the bus if it does not in time.
  void start();
  // Idempotent: stops heartbeats and closes sockets (finite linger).
  void shutdown();

  // Exact-topic subscription. After start(), waits until the proxy has the subscription.
  void subscribe(const std::string& topic, Handler handler);
  // Every topic starting with prefix ("" for all).
  void subscribe_prefix(const std::string& prefix, Handler handler);

  // Builds the envelope around payload in fbb and sends fbb's buffer without copying it.
  PublishStatus publish(std::string_view topic, flatbuffers::FlatBufferBuilder& fbb,
                        msgs::Payload type, flatbuffers::Offset<void> payload,
                        const PublishOptions& options = {});

  // Direct links. The inbox endpoint ("tcp://127.0.0.1:PORT"), or "" where direct links are
  // off (encrypted or non-loopback bus, or NodeOptions::direct_links false). Call after start().
  const std::string& inbox() const { return inbox_endpoint_; }
  // Sends to another node's inbox without the proxy; lossless while the peer lives (PUSH
  // queues until connected). Also sent through the proxy when tapped. The receiver handles the
  // topic with subscribe_direct(). Throws BusError if direct links are off here.
  PublishStatus send_direct(const std::string& inbox, std::string_view topic,
                            flatbuffers::FlatBufferBuilder& fbb, msgs::Payload type,
                            flatbuffers::Offset<void> payload, const PublishOptions& options = {});
  // A handler for messages arriving in the inbox only: no proxy subscription (which would
  // deliver the tap copy of each message a second time).
  void subscribe_direct(const std::string& topic, Handler handler);

  // Sends an already built Envelope unchanged (bag play): its header keeps the original sender
  // and sequence number. The bytes must verify as an Envelope whose topic is `topic`.
  PublishStatus republish(std::string_view topic, std::string_view envelope_bytes);

  // Request/response: publishes on topic and waits for the response until timeout. Other
  // messages arriving meanwhile are queued and dispatched by the next spin_once().
  // `give_up`, checked about every 100 ms, may end the wait early with a reason (e.g. the
  // server's heartbeats stopped). Heartbeats arriving meanwhile are dispatched at once, so
  // such checks see fresh liveness.
  CallResult call(std::string_view topic, flatbuffers::FlatBufferBuilder& fbb, msgs::Payload type,
                  flatbuffers::Offset<void> payload, std::chrono::milliseconds timeout,
                  const std::function<std::optional<std::string>()>& give_up = {});

  // Several requests at once (to different servers): all are published, then the answers are
  // awaited together until timeout; each may give up on its own (its server died).
  struct Request {
    std::string topic;
    flatbuffers::FlatBufferBuilder* fbb = nullptr;
    msgs::Payload type = msgs::Payload::NONE;
    flatbuffers::Offset<void> payload;
    std::function<std::optional<std::string>()> give_up;
  };
  std::vector<CallResult> call_many(std::vector<Request>& requests, std::chrono::milliseconds timeout);
  // Waits until done() holds (checked about every 100 ms and after every heartbeat), up to
  // timeout, handling arriving messages as call() does. Returns done()'s last value. For a
  // caller that must see a server's first heartbeat before it sends (start-up races).
  bool wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout);
  // Serves requests on topic: handler builds the response into fbb and returns its payload.
  // Exceptions become Error responses; requests past their deadline are dropped and counted.
  struct Reply {
    msgs::Payload type;
    flatbuffers::Offset<void> payload;
  };
  using ServeHandler = std::function<Reply(const Message& request, flatbuffers::FlatBufferBuilder&)>;
  void serve(const std::string& topic, ServeHandler handler);

  // Sends a response to request (its reply_to topic and correlation id).
  PublishStatus respond(const Message& request, flatbuffers::FlatBufferBuilder& fbb,
                        msgs::Payload type, flatbuffers::Offset<void> payload);

  // Messages on this topic are dispatched to their handlers even while call() waits (as
  // heartbeats are): for progress reports that must show while a request runs.
  void dispatch_during_calls(const std::string& topic) { call_dispatch_.push_back(topic); }
  // Dispatches queued and incoming messages, waiting at most timeout for the first one.
  // Returns the number of messages dispatched.
  size_t spin_once(std::chrono::milliseconds timeout);
  // Spins until stop becomes true (checked at least every 100 ms).
  void spin(const std::atomic<bool>& stop);

  // Waits until every subscription made so far has reached the proxy.
  void sync();

  void set_state(msgs::NodeState state) { state_.store(state); }
  const NodeStats& stats() const { return stats_; }
  const std::string& name() const { return options_.name; }
  uint64_t instance() const { return instance_; }
  const std::string& bus() const { return options_.bus; }
  const std::string& reply_topic() const { return reply_topic_; }
  std::shared_ptr<zmq::context_t> context() const { return context_; }

 private:
  struct Subscription {
    std::string topic;
    bool prefix;
    Handler handler;
    bool direct_only = false;
  };

  void add_subscription(Subscription sub);
  std::optional<Message> receive(std::chrono::milliseconds timeout);
  std::optional<Message> next_reply(std::chrono::milliseconds wait);
  // One waiting message, if any; `took` tells an invalid (dropped) one from none waiting.
  std::optional<Message> take_from(zmq::socket_t& socket, bool& took);
  void open_inbox();
  zmq::socket_t& outbox(const std::string& inbox);
  bool tapped(std::string_view topic);  // does anyone subscribe to topic through the proxy?
  void read_subscription_changes();
  void dispatch(const Message& message);
  void heartbeat_loop();
  void probe_until_echo(const std::string& probe_topic);
  uint64_t next_seq(std::string_view topic);

  NodeOptions options_;
  std::shared_ptr<zmq::context_t> context_;
  std::unique_ptr<zmq::socket_t> pub_;
  std::unique_ptr<zmq::socket_t> sub_;
  std::unique_ptr<zmq::socket_t> inbox_;  // PULL, bound on loopback (direct links)
  std::string inbox_endpoint_;
  // PUSH sockets to peers' inboxes, most recently used last; a few are kept.
  std::vector<std::pair<std::string, std::unique_ptr<zmq::socket_t>>> outboxes_;
  std::map<std::string, int, std::less<>> subscribed_;  // through the proxy, by prefix (tapped())
  bool inbox_first_ = false;  // alternates which socket is read first: neither starves
  uint64_t instance_;
  std::string reply_topic_;
  std::vector<Subscription> subscriptions_;
  std::vector<std::string> call_dispatch_;
  std::deque<Message> queued_;
  std::map<std::string, uint64_t, std::less<>> seqs_;
  SequenceTracker tracker_;
  NodeStats stats_;
  std::atomic<msgs::NodeState> state_{msgs::NodeState::Starting};
  uint64_t call_counter_ = 0;
  uint64_t probe_counter_ = 0;
  bool started_ = false;
  bool shut_down_ = false;
  std::atomic<bool> heartbeat_stop_{false};
  std::thread heartbeat_thread_;
  double start_mono_s_ = 0;
};

}  // namespace chatsim::bus
