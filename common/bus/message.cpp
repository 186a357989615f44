#include "common/bus/message.hpp"

namespace chatsim::bus {

bool Message::verify() const {
  if (body_.size() < 8) return false;
  flatbuffers::Verifier verifier(data(), body_.size());
  return msgs::VerifyEnvelopeBuffer(verifier);
}

std::string_view Message::correlation_id() const { return view(header().correlation_id()); }

}  // namespace chatsim::bus
