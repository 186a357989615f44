#include "agents/language/lane_names.hpp"

#include <algorithm>

namespace chatsim::agents::language {
namespace {

struct Role {
  const char* word;   // as said before "lane"
  const char* role;
  int side;
};

constexpr Role kRoles[] = {
    {"bus", "bus", 0},         {"buses", "bus", 0},       {"turn", "turn", 0},      {"turning", "turn", 0},
    {"filter", "turn", 0},     {"left-turn", "turn", 1},  {"right-turn", "turn", -1}, {"cycle", "cycle", 0},
    {"bike", "cycle", 0},      {"bicycle", "cycle", 0},   {"tram", "tram", 0},      {"taxi", "taxi", 0},
    {"hov", "hov", 0},         {"carpool", "hov", 0}};

// Id words a map may use for each role.
std::vector<std::string> id_words(const std::string& role) {
  if (role == "turn") return {"turn", "turning", "pocket", "filter"};
  if (role == "cycle") return {"cycle", "bike", "bicycle"};
  if (role == "hov") return {"hov", "carpool"};
  return {role};
}

}  // namespace

std::optional<LaneName> find_lane_name(const std::vector<std::string>& w) {
  for (size_t i = 1; i < w.size(); ++i) {
    if (w[i] != "lane" && w[i] != "lanes" && w[i] != "pocket") continue;
    for (const auto& r : kRoles) {
      if (w[i - 1] != r.word) continue;
      LaneName name{r.role, i - 1, i + 1};
      int side = r.side;
      // "the left turn lane": the side comes first.
      if (name.use == "turn" && side == 0 && i >= 2 && (w[i - 2] == "left" || w[i - 2] == "right")) {
        side = w[i - 2] == "left" ? 1 : -1;
        name.begin = i - 2;
      }
      if (side != 0) name.use += side > 0 ? "_left" : "_right";
      return name;
    }
  }
  return std::nullopt;
}

std::vector<int> lanes_for_use(const scene::LaneMap& map, const std::string& use) {
  const bool turn = use.starts_with("turn");
  const int side = use == "turn_left" ? 1 : use == "turn_right" ? -1 : 0;
  std::vector<int> out;
  for (const auto& word : id_words(turn ? "turn" : use))
    for (int lane : map.named(word))
      if (std::find(out.begin(), out.end(), lane) == out.end()) out.push_back(lane);
  if (!out.empty() || !turn) return out;
  for (size_t i = 0; i < map.lanes().size(); ++i) {
    const int opens = map.diverges(int(i));
    if (opens != 0 && (side == 0 || opens == side)) out.push_back(int(i));
  }
  return out;
}

}  // namespace chatsim::agents::language
