#pragma once
// Building Error payloads: what an exception or a refusal becomes on the bus.
#include <string_view>

#include <flatbuffers/flatbuffers.h>

#include "msgs/envelope_generated.h"

namespace chatsim::bus {

inline flatbuffers::Offset<msgs::Error> make_error(flatbuffers::FlatBufferBuilder& fbb,
                                                   msgs::ErrorCode code, std::string_view message,
                                                   std::string_view node,
                                                   std::string_view cause = {}) {
  return msgs::CreateError(fbb, code, fbb.CreateString(message), fbb.CreateString(node),
                           fbb.CreateString(cause));
}

inline const char* error_code_name(msgs::ErrorCode code) { return msgs::EnumNameErrorCode(code); }

}  // namespace chatsim::bus
