// "undo that": the state each round began from, and going back to it.
#include <memory>
#include <string>

#include "agents/manager/manager.hpp"

namespace chatsim::agents::manager {

void Manager::remember_for_undo(Conversation& c) {
  auto snapshot = std::make_shared<Conversation>(c);
  snapshot->undo.clear();  // each keeps only its own state
  c.undo.push_back(std::move(snapshot));
  if (c.undo.size() > kUndoDepth) c.undo.erase(c.undo.begin());
}

void Manager::do_undo(Conversation& c, const Instruction& in, Round& round) {
  // The newest state kept is this round's own start; the one before it, where the last round began.
  if (!c.undo.empty()) c.undo.pop_back();
  if (c.undo.empty()) {
    c.unresolved.push_back({{"instruction", in.text}, {"reason", "there is no earlier round to undo"}});
    return;
  }
  back_to_round_start(c);
  round.done.push_back("Undid round " + std::to_string(c.rounds.size()) + ".");
}

void Manager::back_to_round_start(Conversation& c) {
  const auto back_to = c.undo.back();
  c.undo.pop_back();
  auto rounds = std::move(c.rounds);
  auto unresolved = std::move(c.unresolved);
  auto undo = std::move(c.undo);
  c = *back_to;
  c.rounds = std::move(rounds);
  c.unresolved = std::move(unresolved);
  c.undo = std::move(undo);
}

}  // namespace chatsim::agents::manager
