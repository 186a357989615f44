#pragma once
// The project manager's "LLM" part: a command split into single-purpose instructions, each
// with the agent work it needs. References ("it", "the Porsche") stay as text; the manager
// resolves them against the edit state.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace chatsim::agents::manager {

struct Instruction {
  // view, delete, restore, add, revise, remove_added, traffic_jam, busy_road, construction_zone, road_block,
  // unclear
  std::string kind;
  std::string text;     // the words of this instruction, as said
  std::string target;   // revise/remove_added/restore: the reference ("it", "the porsche"); add: copy source
  int count = 1;        // add: how many
};

std::vector<Instruction> decompose(const std::string& command);
nlohmann::json to_json(const std::vector<Instruction>& instructions);
std::vector<Instruction> instructions_from_json(const nlohmann::json& j);

// The reference phrase in a revision ("make the added car turn left" -> "the added car"),
// or "" when there is none.
std::string reference_in(const std::string& clause);

}  // namespace chatsim::agents::manager
