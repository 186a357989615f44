#include <algorithm>

#include "agents/language/lane_names.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"

// Clauses that say one thing with no verb, as corrections do ("no, dark green", "no wait, in front
// of it"): what they change is what was spoken of last.
namespace chatsim::agents::manager::detail {
namespace {

// Words around a correction that say nothing of their own ("no, red instead please").
bool is_filler_word(const std::string& x) {
  static const std::vector<std::string> kFiller{"no", "nope", "actually", "rather", "instead", "please", "sorry",
                                                "i", "meant", "mean", "make", "it", "in", "oh", "wait", "hmm", "better",
                                                "let's", "lets", "go", "with", "try", "then", "and", "a", "the"};
  return std::find(kFiller.begin(), kFiller.end(), x) != kFiller.end();
}

}  // namespace

std::optional<std::string> bare_color(const std::vector<std::string>& c) {
  if (lexicon::find_colors(c).empty()) return std::nullopt;
  const bool only_colour = std::all_of(c.begin(), c.end(), [](const std::string& x) {
    return is_filler_word(x) || lexicon::is_color_word(x) || x == "dark" || x == "light" || x == "bright" ||
           x == "pale" || x == "deep";
  });
  if (!only_colour) return std::nullopt;
  std::vector<std::string> colour;
  for (const auto& x : c)
    if (!is_filler_word(x)) colour.push_back(x);
  return text::join(colour);
}

std::optional<std::string> bare_change(const std::vector<std::string>& c) {
  static const std::vector<std::string> kComparatives{"slower", "faster", "quicker", "closer", "nearer", "further",
                                                      "farther", "slowly", "quickly", "fast", "slow"};
  static const std::vector<std::string> kDegree{"a", "bit", "little", "lot", "much", "even", "more", "less", "way",
                                                "slightly", "too", "away", "back", "please", "no", "nope", "still",
                                                "than", "that", "so", "now"};
  const auto in = [](const std::vector<std::string>& list, const std::string& x) {
    return std::find(list.begin(), list.end(), x) != list.end();
  };
  if (std::none_of(c.begin(), c.end(), [&](const std::string& x) { return in(kComparatives, x); })) return std::nullopt;
  if (!std::all_of(c.begin(), c.end(), [&](const std::string& x) { return in(kComparatives, x) || in(kDegree, x); }))
    return std::nullopt;
  std::vector<std::string> said;
  for (const auto& x : c)
    if (x != "no" && x != "nope" && x != "please") said.push_back(x);
  return text::join(said);
}

std::optional<std::string> bare_place(const std::vector<std::string>& said) {
  std::vector<std::string> c = said;
  while (!c.empty() && (c.front() == "no" || c.front() == "nope" || c.front() == "actually" || c.front() == "rather" ||
                        c.front() == "sorry" || c.front() == "oh"))
    c.erase(c.begin());
  static const std::vector<std::string> kPlaces{"in front of", "ahead of", "behind", "next to", "beside", "alongside",
                                                "opposite", "right behind", "just behind", "right in front of",
                                                "just in front of", "directly behind", "directly in front of"};
  // "30 m behind", "20 metres further ahead": a distance before the place.
  const auto amounts = text::quantities(c, text::length_units());
  const size_t from = !amounts.empty() && amounts.front().begin == 0 ? amounts.front().end : 0;
  const std::vector<std::string> place(c.begin() + long(from), c.end());
  const bool opens = std::any_of(kPlaces.begin(), kPlaces.end(), [&](const std::string& p) {
    return text::find_phrase(place, p) == 0;
  }) || (from > 0 && !place.empty() && place.size() <= 3 &&
         text::has_any({place.back()}, {"behind", "ahead", "front"}));  // "2 m forward" moves the view
  // "in the bus lane", "on the left lane": a lane, said alone.
  const auto lane = language::find_lane_name(c);
  const bool in_lane = c.size() > 2 && (c[0] == "in" || c[0] == "on" || c[0] == "into") &&
                       ((lane && lane->begin <= 2) || (std::find(c.begin(), c.end(), "lane") != c.end() && c.size() <= 5));
  if (!opens && !in_lane) return std::nullopt;
  // No verb of its own: "behind the truck, add a car" is an addition.
  const auto verb = [](const std::string& x) {
    const auto& a = add_verbs();
    const auto& d = delete_verbs();
    return std::find(a.begin(), a.end(), x) != a.end() || std::find(d.begin(), d.end(), x) != d.end() ||
           x == "make" || x == "move" || x == "drive" || x == "driving" || x == "going" || x == "coming";
  };
  // ("in the car park": the place's own words are no verb.)
  for (size_t i = 0; i < c.size(); ++i)
    if (verb(c[i]) && !(in_lane && i >= lane->begin && i < lane->end)) return std::nullopt;
  return text::join(c);
}

std::optional<std::string> cleared_place(const std::vector<std::string>& c) {
  if (c.size() < 3 || !text::has_any({c[0]}, {"empty", "clear", "clean", "evacuate", "vacate"})) return std::nullopt;
  const size_t the = c[1] == "the" ? 1 : (c[1] == "out" || c[1] == "up") && c[2] == "the" ? 2 : 0;
  if (the == 0 || the + 1 >= c.size() || text::find_phrase(c, "of") != std::string::npos) return std::nullopt;
  const std::vector<std::string> place(c.begin() + long(the), c.end());
  if (text::has_any(place, {"queue", "queues", "tailback", "jam", "traffic"})) return "remove " + text::join(place);
  if (detail::mentions_vehicle(place) ||
      text::has_any(place, {"view", "camera", "scene", "picture", "frame", "whole", "entire", "everything"}))
    return std::nullopt;
  return "remove all vehicles in " + text::join(place);
}

std::optional<std::string> meant_correction(const std::vector<std::string>& said) {
  std::vector<std::string> c = said;
  while (!c.empty() && text::has_any({c.front()}, {"no", "nope", "sorry", "oh", "oops", "actually", "wait"}))
    c.erase(c.begin());
  size_t from = 0;
  for (const char* marker : {"what i meant was", "what i meant is", "i meant", "i mean", "meant"})
    if (text::find_phrase(c, marker) == 0) {
      from = text::words(marker).size();
      break;
    }
  if (from == 0 || from >= c.size()) return std::nullopt;
  const std::vector<std::string> rest(c.begin() + long(from), c.end());
  // "I meant a Kia Sorento", "I meant dark blue": what was added, said again.
  if (rest[0] != "the" &&
      (rest[0] == "a" || rest[0] == "an" || lexicon::is_color_word(rest[0]) || !lexicon::find_brands(rest).empty()))
    return "make it " + text::join(rest);
  if (const auto place = bare_place(rest)) return "put it " + *place;
  return std::nullopt;
}

}  // namespace chatsim::agents::manager::detail
