// "Add two cones in the lay-by", then "actually make it four": a revision that only says how many
// changes the size of the group added last, more of the same placed as the group was, or fewer.
#include <algorithm>
#include <cmath>
#include <optional>

#include "agents/language/text.hpp"
#include "agents/manager/manager.hpp"

namespace chatsim::agents::manager {
namespace {

// The count a revision says, if it says nothing but a number of vehicles ("make it four", "make
// that 3 cones", "four of them instead"): a whole number with no unit after it.
std::optional<int> count_said(const std::vector<std::string>& w) {
  for (size_t i = 0; i < w.size(); ++i) {
    size_t used = 0;
    const auto n = text::number_at(w, i, &used);
    if (!n || *n != std::floor(*n) || *n < 1 || *n > Manager::kMaxAddedPerInstruction) continue;
    // "make it a van": no count; "make it just one" is one.
    if (w[i] == "a" || w[i] == "an" || (w[i] == "one" && (i == 0 || (w[i - 1] != "just" && w[i - 1] != "only"))))
      continue;
    const size_t after = i + used;
    if (after < w.size() && text::has_any({w[after]}, {"m", "meters", "meter", "km", "kmh", "mph", "degrees", "degree",
                                                       "feet", "ft", "seconds", "s", "percent", "times"}))
      return std::nullopt;
    return int(*n);
  }
  return std::nullopt;
}

}  // namespace

bool Manager::revise_count(Conversation& c, const Instruction& in, const std::vector<int>& targets, Round& round) {
  const auto n = count_said(text::words(in.text));
  if (!n || targets.empty()) return false;
  // The group the target belongs to (the last one added together), else the target alone.
  std::vector<int> group = c.last_group;
  if (std::find(group.begin(), group.end(), targets.back()) == group.end()) group = {targets.back()};
  const AddedVehicle model = c.added[size_t(group.back())];
  if (*n <= int(group.size())) {
    // Fewer: the last ones added go.
    std::vector<int> drop(group.begin() + *n, group.end());
    std::sort(drop.rbegin(), drop.rend());
    for (int i : drop) {
      round.done.push_back("Removed " + c.added[size_t(i)].id + " (" + std::to_string(*n) + " asked).");
      c.added.erase(c.added.begin() + i);
    }
    group.resize(size_t(*n));
    c.last_group = group;
    c.last_ref = group.back();
    return true;
  }
  const nlohmann::json asset_args{{"instruction", in.text}, {"base", model.asset}};
  for (int k = int(group.size()); k < *n; ++k) {
    if (!add_one(c, asset_args, model.intent, in.text, round)) break;
    group.push_back(c.last_ref);
  }
  c.last_group = group;
  round.added_now = group;  // the round ends with "them" meaning the whole group, not the new ones
  return true;
}

}  // namespace chatsim::agents::manager
