#pragma once
// Commands written as a test spec: "Actor: grey Volvo XC90. Start: 25 m ahead in ego lane.
// Speed: 20 km/h." or "Spawn NPC: type=taxi, colour=yellow, position=ego lane 20 m ahead".
#include <optional>
#include <string>
#include <vector>

#include "agents/manager/decompose.hpp"

namespace chatsim::agents::manager {

// The command as one plain sentence ("add a grey volvo xc90 25 m ahead in my lane at 20 km/h"),
// when it has at least two known "key: value" / "key=value" fields; nullopt otherwise.
std::optional<std::string> spec_as_sentence(const std::string& command);

// A sentence with a colon: "Simulate a breakdown: a van stopped in my lane" (a title its detail
// carries out), "clear the works area: the digger and the trailer" (a removal of what follows).
std::vector<Instruction> titled(const std::string& sentence, size_t colon);

}  // namespace chatsim::agents::manager
