// How a round goes on from the last one: it takes its verb ("and the yellow one") or replaces it
// ("no, delete the truck instead").
#include <algorithm>
#include <string>
#include <vector>

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"
#include "agents/manager/manager.hpp"

namespace chatsim::agents::manager {

// "delete the motorbike", then "and the bike in the bus lane too": a round with no verb of its own
// that goes on from the last one takes that round's verb. Read on its own it names a vehicle and
// no verb, which is an addition; "and the yellow one" names none and is not understood.
// "and the next one (along)" repeats the last deletion: what it picked is gone, so the same words
// pick the next.
void Manager::continue_previous_round(const Conversation& c, const std::string& command,
                                      std::vector<Instruction>& instructions) {
  if (c.rounds.empty() || instructions.size() != 1) return;
  if (same_again(c, command, instructions.front())) return;
  if (instructions.front().kind != "add" && instructions.front().kind != "unclear") return;
  const auto w = text::words(command);
  const bool as_well = w.size() >= 2 && w[w.size() - 2] == "as" && w.back() == "well";
  // "sorry, I meant the motorbike" after a deletion: that deletion, of another vehicle.
  const size_t meant = text::find_any(w, {"i meant", "i mean"});
  const bool meant_other = meant != std::string::npos && meant + 3 < w.size() && w[meant + 2] == "the";
  const bool goes_on = !w.empty() && (w.front() == "and" || w.front() == "also" || w.front() == "plus" ||
                                      w.back() == "too" || as_well || meant_other);
  const auto& verbs = detail::add_verbs();
  if (!goes_on || std::any_of(w.begin(), w.end(), [&](const std::string& x) {
        return std::find(verbs.begin(), verbs.end(), x) != verbs.end();
      }))
    return;
  const auto& last = c.rounds.back().at("instructions");
  static const std::string kDelete = "delete: ";  // as run_round records an instruction
  if (last.empty() || !last.back().get<std::string>().starts_with(kDelete)) return;
  instructions.front().kind = "delete";
  const bool next = text::find_phrase(w, "next one") != std::string::npos ||
                    text::find_phrase(w, "one more") != std::string::npos ||
                    (text::find_phrase(w, "the next") != std::string::npos && !detail::mentions_vehicle(w));
  if (next)
    instructions.front().text = last.back().get<std::string>().substr(kDelete.size());
  else if (meant_other)
    instructions.front().text = "remove " + text::join(w, meant + 2);
  else
    instructions.front().text = "remove " + instructions.front().text;
}

// "same again for the coach" after a deletion removes the coach; "the same again but silver" after
// an addition adds another like it, silver. The last round's last instruction, done again.
bool Manager::same_again(const Conversation& c, const std::string& command, Instruction& in) {
  const auto w = text::words(command);
  const size_t at = text::find_any(w, {"same again", "do the same", "same for", "same thing", "likewise"});
  if (at == std::string::npos) return false;
  const auto& last = c.rounds.back().at("instructions");
  if (last.empty()) return false;
  const std::string said = last.back().get<std::string>();
  const size_t colon = said.find(": ");
  if (colon == std::string::npos) return false;
  const std::string kind = said.substr(0, colon);
  std::string again = said.substr(colon + 2);
  const size_t object = text::find_any(w, {"for", "to", "with"});
  const size_t but = text::find_phrase(w, "but");
  if (kind == "delete" && object != std::string::npos && object > at) {
    in = Instruction{"delete", "remove " + text::join(w, object + 1), "", 1};
    return true;
  }
  if (kind != "add") return false;
  // "but silver": the new colour replaces the one said.
  if (but != std::string::npos) {
    const std::vector<std::string> changes(w.begin() + long(but) + 1, w.end());
    const auto colors = lexicon::find_colors(changes);
    std::vector<std::string> words = text::words(again);
    if (!colors.empty()) {
      std::erase_if(words, [](const std::string& x) { return lexicon::is_color_word(x); });
      const auto article = std::find_if(words.begin(), words.end(), [](const std::string& x) {
        return x == "a" || x == "an" || x == "the";
      });
      if (article != words.end()) words.insert(article + 1, colors.front().name);
    }
    again = text::join(words);
  }
  in = Instruction{"add", again, "", 1};
  return true;
}

// "delete the bus", then "no, delete the truck instead": a round that corrects the last one
// (it opens with "no" or "actually" and says "instead" or "I meant") and does the same kind of
// thing, a deletion or a view, replaces it rather than adding to it. Additions have their own
// corrections (a new colour, make or place revises the vehicle).
bool Manager::replaces_last_round(const Conversation& c, const std::string& command,
                                  const std::vector<Instruction>& instructions) const {
  if (c.rounds.empty() || c.undo.empty() || instructions.empty()) return false;
  const auto w = text::words(command);
  const bool opens = !w.empty() && (w.front() == "no" || w.front() == "nope" || w.front() == "actually" ||
                                    w.front() == "sorry" || w.front() == "oops" || text::find_phrase(w, "i meant") == 0);
  const bool corrects = std::find(w.begin(), w.end(), "instead") != w.end() ||
                        text::find_phrase(w, "i meant") != std::string::npos ||
                        text::find_phrase(w, "i mean") != std::string::npos;
  if (!opens || !corrects) return false;
  const std::string kind = instructions.front().kind;
  if (kind != "delete" && kind != "view") return false;
  if (!std::all_of(instructions.begin(), instructions.end(), [&](const Instruction& in) { return in.kind == kind; }))
    return false;
  const auto& last = c.rounds.back().at("instructions");
  return !last.empty() && std::all_of(last.begin(), last.end(), [&](const nlohmann::json& x) {
    return x.get<std::string>().starts_with(kind + ": ");
  });
}

}  // namespace chatsim::agents::manager
