// Queue words of a deletion phrase: which end of a queue, and a queue named by its place.
#include "agents/deletion/queue_phrases.hpp"

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"

namespace chatsim::agents::deletion::detail {

using Words = std::vector<std::string>;

// "the taxi at the front of the queue", "the car at the back of the line": the one with none of
// the others just ahead of it (or behind it), not one in front of the ego.
bool queue_end(Words& p, Selector& s) {
  for (size_t at = 0; at + 3 < p.size(); ++at) {
    const bool head = text::has_any({p[at]}, {"front", "head"});
    if ((!head && !text::has_any({p[at]}, {"back", "end", "rear", "tail"})) || p[at + 1] != "of" ||
        p[at + 2] != "the" || !text::has_any({p[at + 3]}, {"queue", "line", "row"}))
      continue;
    s.order = head ? "queue_head" : "queue_tail";
    s.quantity = "one";
    for (size_t k = at; k < at + 3; ++k) p[k] = "_";  // "queue" stays: it says they wait
    return true;
  }
  // "the last car in the queue", "the first one in line": first and last count along the queue.
  const bool a_line = text::has_any(p, {"line"}) &&
                      !text::has_any(p, {"white", "yellow", "stop line", "center line", "centre line", "give way"});
  if (!a_line && !text::has_any(p, {"queue", "queuing", "queueing", "waiting"})) return false;
  for (auto& x : p)
    if (x == "first" || x == "last") {
      s.order = x == "first" ? "queue_head" : "queue_tail";
      s.quantity = "one";
      x = "_";
      return true;
    }
  return false;
}

// "the drive-thru queue", "the toll line": the queue at that place, said so that the place readers
// find it ("the queue at the drive thru"). Road markings ("the white line") are no queue.
Words queue_place_first(const Words& w) {
  for (size_t q = 2; q < w.size(); ++q) {
    if (!text::has_any({w[q]}, {"queue", "queues", "line", "tailback"})) continue;
    size_t the = q;
    while (the > 0 && w[the - 1] != "the" && q - the < 3) --the;
    if (the == 0 || the == q || w[the - 1] != "the") continue;
    const Words mods(w.begin() + long(the), w.begin() + long(q));
    if (text::has_any(mods, {"white", "yellow", "stop", "center", "centre", "double", "solid", "dashed", "broken",
                             "give", "finish", "start", "front", "back", "same", "other", "next"}) ||
        !lexicon::find_types(mods).empty() || !lexicon::find_colors(mods).empty())
      continue;
    Words out(w.begin(), w.begin() + long(the));
    out.insert(out.end(), {w[q], "at", "the"});
    out.insert(out.end(), mods.begin(), mods.end());
    out.insert(out.end(), w.begin() + long(q) + 1, w.end());
    return out;
  }
  return w;
}

}  // namespace chatsim::agents::deletion::detail
