// Requests and responses on a node: call, call_many (several at once), wait_until, respond, serve.
#include <algorithm>

#include <spdlog/spdlog.h>

#include "common/bus/errors.hpp"
#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"

namespace chatsim::bus {

// While a call waits: heartbeats and topics asked for are handled, other messages are queued
// for later, and only a message on the reply topic is returned.
std::optional<Message> Node::next_reply(std::chrono::milliseconds wait) {
  auto m = receive(wait);
  if (!m) return std::nullopt;
  if (m->topic() == topics::kHeartbeat ||
      std::find(call_dispatch_.begin(), call_dispatch_.end(), m->topic()) != call_dispatch_.end()) {
    dispatch(*m);
    return std::nullopt;
  }
  if (m->topic() == reply_topic_) return m;
  queued_.push_back(std::move(*m));
  return std::nullopt;
}

CallResult Node::call(std::string_view topic, flatbuffers::FlatBufferBuilder& fbb,
                      msgs::Payload type, flatbuffers::Offset<void> payload,
                      std::chrono::milliseconds timeout,
                      const std::function<std::optional<std::string>()>& give_up) {
  const std::string correlation = options_.name + "/" + topics::hex(instance_) + "/" +
                                  std::to_string(++call_counter_);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  PublishOptions po{correlation, reply_topic_,
                    now_ns() + std::chrono::duration_cast<std::chrono::nanoseconds>(timeout).count(),
                    inbox_endpoint_};
  CallResult result;
  if (publish(topic, fbb, type, payload, po) != PublishStatus::Sent) {
    result.error = msgs::ErrorCode::Unavailable;
    result.error_message = "could not send on '" + std::string(topic) + "' (queue full)";
    return result;
  }
  for (;;) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) break;
    // Rounded up: never give up before the deadline the request carries.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - now);
    if (give_up) {
      if (auto reason = give_up()) {
        result.error = msgs::ErrorCode::Unavailable;
        result.error_message = *reason;
        return result;
      }
    }
    auto m = next_reply(std::min(left, std::chrono::milliseconds(100)));
    if (!m) continue;
    if (m->correlation_id() == correlation) {
      result.response = std::move(m);
      return result;
    }
    stats_.late_replies.fetch_add(1, std::memory_order_relaxed);
  }
  result.error = msgs::ErrorCode::DeadlineExceeded;
  result.error_message = "no response on '" + std::string(topic) + "' within " +
                         std::to_string(timeout.count()) + " ms";
  return result;
}

std::vector<CallResult> Node::call_many(std::vector<Request>& requests, std::chrono::milliseconds timeout) {
  std::vector<CallResult> results(requests.size());
  std::vector<std::string> correlation(requests.size());
  std::vector<bool> open(requests.size(), false);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  size_t waiting = 0;
  for (size_t i = 0; i < requests.size(); ++i) {
    correlation[i] = options_.name + "/" + topics::hex(instance_) + "/" + std::to_string(++call_counter_);
    PublishOptions po{correlation[i], reply_topic_,
                      now_ns() + std::chrono::duration_cast<std::chrono::nanoseconds>(timeout).count(),
                      inbox_endpoint_};
    if (publish(requests[i].topic, *requests[i].fbb, requests[i].type, requests[i].payload, po) != PublishStatus::Sent) {
      results[i].error = msgs::ErrorCode::Unavailable;
      results[i].error_message = "could not send on '" + requests[i].topic + "' (queue full)";
      continue;
    }
    open[i] = true;
    ++waiting;
  }
  while (waiting > 0) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) break;
    for (size_t i = 0; i < requests.size(); ++i) {
      if (!open[i] || !requests[i].give_up) continue;
      if (auto reason = requests[i].give_up()) {
        results[i].error = msgs::ErrorCode::Unavailable;
        results[i].error_message = *reason;
        open[i] = false;
        --waiting;
      }
    }
    if (waiting == 0) break;
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - now);
    auto m = next_reply(std::min(left, std::chrono::milliseconds(100)));
    if (!m) continue;
    bool matched = false;
    for (size_t i = 0; i < requests.size(); ++i)
      if (open[i] && m->correlation_id() == correlation[i]) {
        results[i].response = std::move(m);
        open[i] = false;
        --waiting;
        matched = true;
        break;
      }
    if (!matched) stats_.late_replies.fetch_add(1, std::memory_order_relaxed);
  }
  for (size_t i = 0; i < requests.size(); ++i)
    if (open[i]) {
      results[i].error = msgs::ErrorCode::DeadlineExceeded;
      results[i].error_message = "no response on '" + requests[i].topic + "' within " + std::to_string(timeout.count()) + " ms";
    }
  return results;
}

bool Node::wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) return false;
    auto m = receive(std::min(std::chrono::ceil<std::chrono::milliseconds>(deadline - now), std::chrono::milliseconds(100)));
    if (!m) continue;
    if (m->topic() == topics::kHeartbeat ||
        std::find(call_dispatch_.begin(), call_dispatch_.end(), m->topic()) != call_dispatch_.end()) {
      dispatch(*m);
    } else if (m->topic() == reply_topic_) {
      stats_.late_replies.fetch_add(1, std::memory_order_relaxed);  // no call is open
    } else {
      queued_.push_back(std::move(*m));
    }
  }
  return true;
}

PublishStatus Node::respond(const Message& request, flatbuffers::FlatBufferBuilder& fbb,
                            msgs::Payload type, flatbuffers::Offset<void> payload) {
  const std::string_view reply_to = view(request.header().reply_to());
  if (reply_to.empty()) {
    fbb.Clear();
    return PublishStatus::Sent;  // a plain publication wants no answer
  }
  PublishOptions po;
  po.correlation_id = std::string(request.correlation_id());
  const std::string_view inbox = view(request.header().reply_endpoint());
  if (!inbox.empty()) return send_direct(std::string(inbox), reply_to, fbb, type, payload, po);
  return publish(reply_to, fbb, type, payload, po);
}

void Node::serve(const std::string& topic, ServeHandler handler) {
  subscribe(topic, [this, handler = std::move(handler)](const Message& request) {
    const int64_t deadline = request.header().deadline_ns();
    if (deadline != 0 && now_ns() > deadline) {
      stats_.expired.fetch_add(1, std::memory_order_relaxed);
      spdlog::warn("[{}] dropped a request from '{}' on '{}': its deadline had passed",
                   options_.name, request.sender(), request.topic());
      return;
    }
    flatbuffers::FlatBufferBuilder fbb(1024);
    Reply reply{};
    const auto previous = state_.exchange(msgs::NodeState::Busy);
    try {
      reply = handler(request, fbb);
    } catch (const std::exception& e) {
      fbb.Clear();
      reply = {msgs::Payload::Error,
               make_error(fbb, msgs::ErrorCode::Internal, "request failed", options_.name, e.what())
                   .Union()};
    }
    state_.store(previous);
    respond(request, fbb, reply.type, reply.payload);
  });
}

}  // namespace chatsim::bus
