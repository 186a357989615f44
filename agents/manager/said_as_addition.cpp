// Clauses that add vehicles without saying "add": a new vehicle made to do something ("have a
// tahoe come from the right"), a place filled with vehicles ("fill the bays").
#include "agents/language/lane_names.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"

namespace chatsim::agents::manager::detail {

using Words = std::vector<std::string>;

// "have a tahoe come from the right", "let a bus pull out", "send a coach through booth 3": a new
// vehicle made to do something.
Words causative_addition(const Words& c) {
  if (c.size() < 3 || (c[0] != "have" && c[0] != "let" && c[0] != "make" && c[0] != "get" && c[0] != "send")) return c;
  if (c[1] != "a" && c[1] != "an" && !(text::is_number_word(c[1]) && c[1] != "half")) return c;
  const auto types = lexicon::find_types(Words(c.begin() + 1, c.end()));
  const auto brands = lexicon::find_brands(Words(c.begin() + 1, c.end()));
  const bool vehicle = (!types.empty() && types.front().begin <= 4 && !types.front().type.living()) ||
                       (!brands.empty() && brands.front().begin <= 4);
  if (!vehicle) return c;
  Words out{"add"};
  out.insert(out.end(), c.begin() + 1, c.end());
  return out;
}

// "make the parking on the left full of cars", "fill the kerb with vans", "line the street with
// parked cars": a place filled with vehicles is a row of them parked there.
Words fill_addition(const Words& c) {
  if (c.size() < 4 || (c[0] != "make" && c[0] != "fill" && c[0] != "line" && c[0] != "pack" && c[0] != "have"))
    return c;
  const size_t link = text::find_any(c, {"full of", "filled with", "packed with", "lined with", "with"});
  // "fill the car park", "fill up the parking lane": a place for parking, filled with parked cars.
  const auto area = language::find_lane_name(c);
  if (link == std::string::npos && (c[0] == "fill" || c[0] == "pack") &&
      ((area && (area->use == "car_park" || area->use == "lay_by")) ||
       text::has_any(c, {"parking", "bays", "bay", "spaces", "spots", "stalls"}))) {  // "fill the empty bays"
    Words out{"add", "a", "row", "of", "parked", "cars", "in"};
    out.insert(out.end(), c.begin() + (c[1] == "up" ? 2 : 1), c.end());
    return out;
  }
  if (link == std::string::npos || link < 2) return c;
  const size_t noun_from = link + (c[link] == "with" ? 1 : 2);
  const auto types = lexicon::find_types(Words(c.begin() + long(noun_from), c.end()));
  if (types.empty() || !types.front().plural || types.front().type.living()) return c;
  Words out{"add", "a", "row", "of", "parked"};
  out.insert(out.end(), c.begin() + long(noun_from + types.front().begin), c.begin() + long(noun_from + types.front().end));
  out.push_back("in");
  out.insert(out.end(), c.begin() + 1, c.begin() + long(link));
  return out;
}

// "add a motorbike behind the one that's already there", "a van next to the existing one": the
// recorded vehicle of the kind being added.
Words existing_one(const Words& c) {
  static const char* kPhrases[] = {"the one that is already there", "the one which is already there",
                                   "the one that already there", "the one thats already there", "the one already there",
                                   "the one that already in the scene", "the one already in the scene",
                                   "the existing one", "the one that there", "the one there"};
  for (const char* phrase : kPhrases) {
    const size_t at = text::find_phrase(c, phrase);
    if (at == std::string::npos) continue;
    const auto types = lexicon::find_types(Words(c.begin(), c.begin() + long(at)));
    if (types.empty() || types.front().type.living()) return c;
    Words out(c.begin(), c.begin() + long(at));
    out.push_back("the");
    const auto& t = types.front();
    out.insert(out.end(), c.begin() + long(t.begin), c.begin() + long(t.end));
    out.insert(out.end(), c.begin() + long(at + text::words(phrase).size()), c.end());
    return out;
  }
  return c;
}

}  // namespace chatsim::agents::manager::detail
