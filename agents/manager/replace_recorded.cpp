#include <optional>

#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"
#include "agents/manager/manager.hpp"

// "Swap the bendy bus for a double-decker", "replace the truck with a police car": a recorded
// vehicle cannot be changed, so it goes and the new one takes its place.
namespace chatsim::agents::manager {

namespace {

struct Swap {
  std::string old_one, new_one;  // as said
};

// The two sides of "replace|swap|switch|exchange|trade X (out) with|for Y", when both name
// vehicles.
std::optional<Swap> read_swap(const std::vector<std::string>& w) {
  if (w.size() < 4 || !text::has_any({w.front()}, {"replace", "swap", "switch", "exchange", "trade"})) return std::nullopt;
  for (size_t i = 2; i + 1 < w.size(); ++i) {
    if (w[i] != "with" && w[i] != "for" && w[i] != "by") continue;
    const size_t old_end = w[i - 1] == "out" ? i - 1 : i;
    const std::vector<std::string> old_one(w.begin() + 1, w.begin() + long(old_end)), new_one(w.begin() + long(i) + 1, w.end());
    if (old_one.empty() || !detail::mentions_vehicle(old_one) || !detail::mentions_vehicle(new_one)) return std::nullopt;
    return Swap{text::join(old_one), text::join(new_one)};
  }
  return std::nullopt;
}

}  // namespace

bool Manager::replace_recorded(Conversation& c, const Instruction& in, Round& round) {
  const auto swap = read_swap(text::words(in.text));
  if (!swap || !resolve(c, swap->old_one).empty()) return false;  // an added one is revised
  const size_t removed_before = c.removed.size(), unresolved_before = c.unresolved.size();
  do_delete(c, {"delete", "remove " + swap->old_one, "", 1}, round);
  if (c.removed.size() == removed_before) {
    // Nothing recorded matched either: say so for the whole request.
    c.unresolved.erase(c.unresolved.begin() + long(unresolved_before), c.unresolved.end());
    c.unresolved.push_back({{"instruction", in.text},
                            {"reason", "no vehicle, added or recorded, matches '" + swap->old_one + "' to replace"}});
    return true;
  }
  do_add(c, {"add", "add " + swap->new_one + " in its place", "", 1}, round);
  return true;
}

}  // namespace chatsim::agents::manager
