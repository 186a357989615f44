// libFuzzer: bytes from the bus. Verification must reject what is malformed; what passes must
// be safe to read field by field and to print as JSON.
#include <cstdint>
#include <string_view>

#include "common/bus/message_json.hpp"
#include "msgs/envelope_generated.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const chatsim::bus::MessagePrinter printer;
  flatbuffers::Verifier verifier(data, size);
  if (!chatsim::msgs::VerifyEnvelopeBuffer(verifier)) return 0;
  const auto* env = chatsim::msgs::GetEnvelope(data);
  const auto* h = env->header();
  size_t sum = (h->topic() ? h->topic()->size() : 0) + (h->sender() ? h->sender()->size() : 0) + h->seq();
  switch (env->payload_type()) {
    case chatsim::msgs::Payload::AgentRequest:
      if (const auto* r = env->payload_as_AgentRequest(); r && r->args_json()) sum += r->args_json()->size();
      break;
    case chatsim::msgs::Payload::Image:
      if (const auto* i = env->payload_as_Image(); i && i->data()) sum += i->data()->size();
      break;
    case chatsim::msgs::Payload::ChatRequest:
      if (const auto* c = env->payload_as_ChatRequest(); c && c->command()) sum += c->command()->size();
      break;
    default:
      break;
  }
  const std::string json = printer.to_json({reinterpret_cast<const char*>(data), size});
  return int(sum + json.size()) & 0;
}
