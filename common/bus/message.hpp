#pragma once
// A received bus message: the bytes ZeroMQ delivered, verified once, read in place.
#include <string_view>

#include <zmq.hpp>

#include "msgs/envelope_generated.h"

namespace chatsim::bus {

class Message {
 public:
  // Takes the body frame; call verify() before any accessor.
  explicit Message(zmq::message_t body) : body_(std::move(body)) {}

  // Runs the FlatBuffers Verifier; false for anything that is not a well-formed Envelope.
  bool verify() const;

  const msgs::Envelope& envelope() const { return *msgs::GetEnvelope(body_.data()); }
  const msgs::Header& header() const { return *envelope().header(); }
  std::string_view topic() const { return header().topic()->string_view(); }
  std::string_view sender() const { return header().sender()->string_view(); }
  std::string_view correlation_id() const;
  msgs::Payload type() const { return envelope().payload_type(); }

  template <class T>
  const T* payload() const {
    return envelope().payload_as<T>();
  }

  const uint8_t* data() const { return static_cast<const uint8_t*>(body_.data()); }
  size_t size() const { return body_.size(); }

 private:
  zmq::message_t body_;
};

inline std::string_view view(const flatbuffers::String* s) {
  return s == nullptr ? std::string_view() : s->string_view();
}

}  // namespace chatsim::bus
