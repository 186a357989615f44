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
  const bool opens = std::any_of(kPlaces.begin(), kPlaces.end(), [&](const std::string& p) {
    return text::find_phrase(c, p) == 0;
  });
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
  if (std::any_of(c.begin(), c.end(), verb)) return std::nullopt;
  return text::join(c);
}

}  // namespace chatsim::agents::manager::detail
