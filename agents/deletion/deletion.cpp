#include "agents/deletion/deletion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>

#include "agents/deletion/lane_relation.hpp"
#include "agents/deletion/queue_phrases.hpp"
#include "agents/language/lane_names.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"

namespace chatsim::agents::deletion {
namespace {

using Words = std::vector<std::string>;

// Splits "the yellow car and the green one" into noun phrases.
// Words that name nothing: "the van as well, please".
bool is_filler(const std::string& w) {
  return text::has_any({w}, {"well", "too", "also", "please", "now", "then", "again", "anyway", "instead"});
}

std::vector<Words> phrases(const Words& w, size_t begin, size_t end) {
  std::vector<Words> out(1);
  for (size_t i = begin; i < end; ++i) {
    // "the car heading the same way as it": "as it" ends the phrase's relation, no new phrase.
    if (w[i] == "as" && i > begin && (w[i - 1] == "way" || w[i - 1] == "direction") && i + 1 < end &&
        (w[i + 1] == "it" || w[i + 1] == "that" || w[i + 1] == "them")) {
      ++i;
      continue;
    }
    if (w[i] == "and" || w[i] == "or" || w[i] == "plus" || w[i] == "as") {
      if (!out.back().empty()) out.emplace_back();
      continue;
    }
    // "the red car, the truck and the motorbike" (the commas are gone): a determiner right after
    // a vehicle noun starts the next phrase; "the car behind the bus" keeps its relation.
    if ((w[i] == "the" || w[i] == "a" || w[i] == "an") && i > begin && !out.back().empty()) {
      const auto nouns = lexicon::find_types(out.back());
      if (!nouns.empty() && nouns.back().end == out.back().size()) out.emplace_back();
    }
    out.back().push_back(w[i]);
  }
  // "the broken-down car as well": a phrase of fillers only names nothing.
  std::erase_if(out, [](const Words& p) { return std::all_of(p.begin(), p.end(), is_filler); });
  return out;
}

// "the tractor": an English noun the interpreter does not know where the thing to delete is
// named; nothing in a scene is one, so the request is refused rather than guessed.
std::optional<std::string> unknown_head(const Words& said) {
  if (!lexicon::find_types(said).empty()) return std::nullopt;
  Words p = said;  // "clear the service road": a lane's name is no thing to delete
  if (const auto name = language::find_lane_name(said))
    for (size_t k = name->begin; k < name->end; ++k) p[k] = "_";
  for (const auto& word : p) {
    static const char* skip[] = {"the", "a", "an", "that", "this", "those", "these", "every", "all", "each", "any", "my",
                                 "there", "here", "thanks", "thank", "you", "_"};
    static const char* pronouns[] = {"whatever", "anything", "something", "whichever", "everything", "one", "ones"};
    if (std::find(std::begin(pronouns), std::end(pronouns), word) != std::end(pronouns)) return std::nullopt;
    if (std::find(std::begin(skip), std::end(skip), word) != std::end(skip) || is_filler(word) ||
        lexicon::is_color_word(word) || text::is_number_word(word))
      continue;
    if (lexicon::is_domain_word(word)) return std::nullopt;
    // "the zorblax": a make or name nobody knows; recorded objects carry no make to select by.
    if (!lexicon::is_english_word(word) && !lexicon::unknown_vehicle_name({word}, 0)) return std::nullopt;
    return word;
  }
  return std::nullopt;
}

// The lane a phrase names, if any.
std::optional<std::string> lane_words(const Words& p) {
  if (text::has_any(p, {"my lane", "our lane", "same lane", "ego lane", "this lane"})) return "ego";
  if (text::has_any(p, {"middle lane", "center lane", "central lane"})) return "middle";
  // The fast lane is next to the other way's traffic: the left one where traffic keeps right.
  if (text::has_any(p, {"fast lane", "outside lane", "passing lane", "overtaking lane", "offside lane", "inner lane"}))
    return "inner";
  if (text::has_any(p, {"slow lane", "inside lane", "nearside lane", "curb lane", "outer lane"})) return "outer";
  if (text::has_any(p, {"left lane", "left hand lane"})) return "left";
  if (text::has_any(p, {"right lane", "right hand lane"})) return "right";
  if (text::has_any(p, {"oncoming", "other carriageway", "opposite carriageway", "opposite direction",
                        "other direction", "the other way", "opposite way", "coming toward", "toward me", "toward us",
                        "coming at me", "coming at us"}))
    return "oncoming";
  // "the car waiting to leave the gas station", "the van coming out of the driveway": on a lane that
  // meets the road (no map names a gas station); pulling out of a bay or a car park is not, nor
  // out of a lane named by its use (its words are blanked to "_": the lane_use says where).
  if (const size_t at = text::find_any(p, {"waiting to leave", "waiting to exit", "waiting to pull out of",
                                           "about to pull out of", "about to leave", "waiting to come out of",
                                           "coming out of", "pulling out of", "emerging from"});
      at != std::string::npos) {
    const Words place(p.begin() + long(at), p.end());
    if (std::find(place.begin(), place.end(), "_") == place.end() &&
        !text::has_any(place, {"space", "bay", "spot", "parking", "kerb", "curb", "stall", "car park", "carpark", "lot",
                               "garage"}))
      return "cross";
  }
  if (text::has_any(p, {"main road", "main street", "major road", "main carriageway", "bigger road", "big road"}))
    return "main";  // the ego's road or the one it joins (selection.cpp)
  // "at the crossing" is a place; "the person crossing the road" says what the person does.
  if (text::has_any(p, {"side street", "side road", "cross street", "crossroads", "junction", "intersection",
                        "the crossing", "a crossing", "cross traffic", "side streets", "farm track", "dirt track",
                        "dirt road", "track", "alley", "alleyway", "driveway"}))
    return "cross";
  if (text::has_any(p, {"parking lane", "parking bay", "bus bay", "bus stop", "parking spot", "parking space"}))
    return "parking";
  if (text::has_any(p, {"slip road", "on ramp", "ramp", "merging lane", "acceleration lane", "entry lane", "joining",
                        "lane that ends", "lane which ends", "ending lane", "lane ending", "lane that merges",
                        "the exit", "an exit", "exit lane", "off ramp", "exiting", "leaving the road"}))
    return "ramp";
  if (text::has_any(p, {"hard shoulder", "shoulder", "verge", "emergency lane", "roadside"})) return "shoulder";
  return std::nullopt;
}

// "the car parked closest to the police car", "the van behind the bus": the head, the object it
// is placed by, and how. None when no object ("the") follows the relation word.
struct Relation {
  Words head, reference;
  std::string relation;
};
std::optional<Relation> split_relation(const Words& p) {
  static const std::pair<const char*, const char*> kRelations[] = {
      {"closest to", "near"}, {"nearest to", "near"}, {"nearest", "near"},    {"closest", "near"},
      {"close to", "near"},   {"near", "near"},       {"next to", "beside"},  {"beside", "beside"},
      {"alongside", "beside"}, {"behind", "behind"},  {"in front of", "front"}, {"ahead of", "front"}};
  for (const auto& [phrase, relation] : kRelations) {
    const size_t at = text::find_phrase(p, phrase);
    const size_t after = at + text::words(phrase).size();
    if (at == std::string::npos || at == 0 || after >= p.size() || (p[after] != "the" && p[after] != "that")) continue;
    const Words reference(p.begin() + long(after), p.end());
    const auto types = lexicon::find_types(reference);
    if (types.empty() || types.front().begin > 3) continue;
    // "the bus stop", "the parking lane": a place, not an object.
    const size_t noun_end = types.front().end;
    if (noun_end < reference.size() && text::has_any({reference[noun_end]}, {"stop", "bay", "lane", "station", "shelter"}))
      continue;
    return Relation{Words(p.begin(), p.begin() + long(at)), reference, relation};
  }
  return std::nullopt;
}

// "within 16 m of me", "closer than 20 metres", "more than 30 m away": a bound on the distance
// from the ego, said by the words just before (or after) the amount.
void read_distance_bounds(const Words& p, Selector& s) {
  for (const auto& q : text::quantities(p, text::length_units())) {
    const double metres = q.value * text::meters_per(q.unit).value_or(1.0);
    const Words before(p.begin() + long(q.begin >= 3 ? q.begin - 3 : 0), p.begin() + long(q.begin));
    const Words after(p.begin() + long(q.end), p.begin() + long(std::min(p.size(), q.end + 2)));
    const auto ends_with = [&](std::initializer_list<std::string_view> phrases) {
      for (const auto phrase : phrases) {
        const size_t at = text::find_phrase(before, phrase);
        if (at != std::string::npos && at + text::words(phrase).size() == before.size()) return true;
      }
      return false;
    };
    if (ends_with({"within", "less than", "closer than", "nearer than", "under", "inside", "no more than",
                   "no further than", "no farther than", "at most"}) ||
        text::has_any(after, {"or closer", "or less", "or nearer"}))
      s.within_m = metres;
    else if (ends_with({"more than", "further than", "farther than", "beyond", "over", "at least", "past"}) ||
             text::has_any(after, {"or more", "or further", "or farther"}))
      s.beyond_m = metres;
  }
}

// "the second car", "the last parked car", "two cars", "both cars": which of the matches, and how
// many.
void read_order_and_count(const Words& p, const std::vector<lexicon::TypeMention>& types, Selector& s) {
  if (text::has_any(p, {"closest", "nearest", "near", "close"})) s.order = "nearest";
  else if (text::has_any(p, {"farthest", "furthest", "far", "most distant"})) s.order = "farthest";
  // "the last parked car", "the second to last truck": counted from the far end of the row.
  else if (text::has_any(p, {"last", "penultimate", "final"})) s.order = "farthest";
  // "the largest vehicle", "the smallest car": by the size of its box.
  // "the larger of the two", "the slower of the cars ahead": a comparative picks one as well.
  if (text::has_any(p, {"largest", "biggest", "longest", "tallest", "bulkiest", "heaviest", "larger", "bigger",
                        "longer", "taller"}))
    s.order = "largest";
  else if (text::has_any(p, {"smallest", "tiniest", "shortest", "littlest", "smaller", "shorter"})) s.order = "smallest";
  else if (text::has_any(p, {"slowest", "slower"})) s.order = "slowest";
  else if (text::has_any(p, {"fastest", "faster", "quickest", "quicker", "speediest"})) s.order = "fastest";
  if (s.order == "largest" || s.order == "smallest" || s.order == "slowest" || s.order == "fastest") s.quantity = "one";
  if (text::has_any(p, {"penultimate"})) {
    s.nth = 2;
    s.quantity = "one";
  }
  for (size_t i = 0; i < p.size(); ++i)
    if (int k = text::ordinal_value(p[i])) {
      s.nth = k;
      if (!s.order) s.order = "nearest";
      s.quantity = "one";
    }
  // "two cars", "3 trucks"
  if (!types.empty())
    for (size_t i = 0; i < types.front().begin; ++i) {
      size_t used = 0;
      const auto v = text::number_at(p, i, &used);
      // "the slower of the two cars": how many there are to pick from, not how many to remove.
      const bool group = i >= 2 && p[i - 1] == "the" && p[i - 2] == "of";
      if (v && *v >= 2 && i + used <= types.front().begin && !group) {
        s.quantity = "n";
        s.n = int(*v);
      }
    }
  if (s.order && s.quantity == "all" && !text::has_any(p, {"all", "every", "each"})) s.quantity = "one";
  // "both cars", "both of the parked cars": two of them, the nearest two (not "on both sides").
  const size_t both = text::find_phrase(p, "both");
  if (both != std::string::npos && s.quantity == "all" && !types.empty() && types.front().plural &&
      both < types.front().begin && types.front().begin - both <= 4) {
    s.quantity = "n";
    s.n = 2;
  }
}

Selector parse_phrase(const Words& said_in, const Selector* previous) {
  Selector s;
  const Words said = detail::queue_place_first(said_in);
  // "the bike in the bus lane", "the left-turn lane": a lane named by its use; its words say
  // neither what the object is nor on which side it stands.
  Words p = said;
  if (const auto beyond = language::find_beyond_place(said)) {  // "everything on the other side of the busway"
    s.beyond_use = beyond->use;
    for (size_t k = beyond->begin; k < beyond->end; ++k) p[k] = "_";
  }
  if (const auto name = language::find_lane_name(p)) {
    s.lane_use = name->use;
    for (size_t k = name->begin; k < name->end; ++k) p[k] = "_";
  } else if (const size_t at = text::find_any(p, {"waiting to turn", "queuing to turn", "queueing to turn",
                                                    "lined up to turn", "about to turn"});
             at != std::string::npos && at + 3 < p.size() && (p[at + 3] == "left" || p[at + 3] == "right")) {
    s.lane_use = "turn_" + p[at + 3];  // in a turn lane when the map has one (selection.cpp)
    p[at + 3] = "_";
  } else if (const auto place = language::find_place_word(p)) {
    s.lane_use = place->use;  // "the cars at the pumps": its words stay for the other readings
  }
  const auto types = lexicon::find_types(p);
  if (!types.empty()) {
    const auto& t = types.front().type;
    s.category = t.type == "object" ? "" : t.scene_prefix;
    s.noun = text::join(p, types.front().begin, types.front().end);
    if (types.front().plural) s.quantity = "all";
  } else if (previous != nullptr) {  // "the green one"
    s.category = previous->category;
    s.noun = previous->noun;
  } else {
    s.noun = "vehicle";  // nothing named: any vehicle (not a preference for cars)
    // "remove the queue at the barrier": every vehicle in it.
    if (text::has_any(p, {"queue", "queues", "tailback"}) && !text::has_any(p, {"front", "head", "back", "end", "tail"}))
      s.quantity = "all";
  }
  if (!s.category.empty() || previous == nullptr) {
    if (s.category.empty() && text::has_any(p, {"ones", "those"})) s.category = "vehicle";  // "the red ones"
    if (text::has_any(p, {"ones", "those"})) s.quantity = "all";
  }
  if (text::has_any(p, {"everything", "all objects", "anything", "every object"})) {
    s.category = "";
    s.quantity = "all";
  }
  if (text::has_any(p, {"all", "every", "each", "any"})) s.quantity = "all";
  const auto colors = lexicon::find_colors(p);
  if (!colors.empty()) s.color = lexicon::color_class(colors.front().rgb);
  // "near the junction" narrows nothing: only beyond or short of it does.
  if (const auto junction = language::blank_junction_place(p); junction != "near") s.junction = junction;
  s.lane = lane_words(p);
  // "across the street", "on my side": a half of the road, parked cars included.
  if (text::has_any(p, {"across the street", "across the road", "far side", "other side of the road", "other side of the street",
                        "opposite side", "over the road", "across from me", "across from us"}))
    s.road_side = "far";
  else if (text::has_any(p, {"my side", "our side", "this side", "near side", "nearside", "same side"}))
    s.road_side = "near";
  // "coming down the hill / the road": toward the ego, which is going up it.
  if (text::has_any(p, {"coming toward", "toward me", "toward us", "approaching", "coming at", "coming down",
                        "heading down", "descending", "downhill"}))
    s.approaching = true;
  // "the truck behind it": placed by the object the phrase before named (or, with none, the one
  // an earlier round spoke of: select_objects' `it`), not by the ego.
  if (text::has_any(p, {"behind it", "behind that one", "after it", "behind them"})) s.of_previous = "behind";
  else if (text::has_any(p, {"in front of it", "ahead of it", "in front of them"})) s.of_previous = "front";
  else if (text::has_any(p, {"next to it", "beside it", "alongside it", "next to them", "beside them"})) s.of_previous = "beside";
  else if (previous != nullptr && text::has_any(p, {"same way", "same direction"})) s.of_previous = "same_way";
  if (text::has_any(p, {"following me", "following us", "tailing me", "tailing us", "tailgating me", "tailgating us",
                        "on my tail", "on our tail", "right behind me", "right behind us"})) {
    s.lane = "ego";
    s.region = "back";
  }
  // "the truck I'm merging behind", "the car we are following": the ego is behind it, it is ahead.
  for (size_t i = 0; i + 1 < p.size() && !s.of_previous; ++i) {
    const bool ego_subject = p[i] == "im" || (p[i] == "i" && p[i + 1] == "am") || (p[i] == "we" && p[i + 1] == "are");
    for (size_t k = i + 1; ego_subject && k < std::min(p.size(), i + 5); ++k)
      if (p[k] == "behind" || p[k] == "following" || p[k] == "tailing") {
        p[k] = "ahead";
        break;
      }
  }
  // "the left lane" names a lane, not a side: the side words only count outside a lane phrase.
  const bool side_is_lane = s.lane == "left" || s.lane == "right";
  if (s.of_previous) {
  } else if (detail::queue_end(p, s)) {
  } else if (text::has_any(p, {"in front", "ahead", "front"})) s.region = "front";
  else if (text::has_any(p, {"behind", "back", "rear"})) s.region = "back";
  else if (!side_is_lane && text::has_any(p, {"left"})) s.region = "left";
  else if (!side_is_lane && text::has_any(p, {"right"})) s.region = "right";
  // "the cars waiting at the lights", "the last car in the queue": standing in a lane of traffic.
  const bool waiting = text::has_any(p, {"waiting", "queuing", "queueing", "queued", "queue", "at the lights",
                                         "at the light", "at the red light", "in traffic", "held up"});
  if (waiting || text::has_any(p, {"parked", "stopped", "stationary", "static", "not moving", "standing", "still",
                                   "broken down", "stalled", "abandoned", "crashed", "disabled"}))
    s.moving = false;
  else if (text::has_any(p, {"backing", "backs out", "backs up", "reversing", "reverses", "in reverse",
                             "going backwards", "going backward"}))
    s.reversing = true;  // it may stand for most of the clip: moving on the whole says little
  else if (text::has_any(p, {"moving", "driving", "in motion", "traveling", "travelling", "pulling out", "pulling away",
                             "leaving", "exiting", "driving out", "coming out", "drives", "passes", "goes past",
                             "goes by", "comes past", "comes by", "passing by", "drives by"}))
    s.moving = true;
  // "the row of bays on the left", "the cars in the spaces": what stands in a bay is parked.
  s.parked = text::has_any(p, {"parked", "parking", "bay", "bays", "spaces", "spots", "parking space"});
  s.waiting = waiting && !s.parked;
  // "the van that's double parked", "the car blocking my lane": standing in a lane of traffic.
  if (text::has_any(p, {"double parked", "blocking", "stopped in the road", "stopped in the street",
                        "in the middle of the road", "in the middle of the street", "stranded in"})) {
    s.moving = false;
    s.parked = false;
    if (!s.lane) s.lane = "road";
  }
  read_distance_bounds(p, s);
  read_order_and_count(p, types, s);
  return s;
}

}  // namespace

namespace {
std::string metres_text(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::round(m * 10) / 10);
  return buf;
}
}  // namespace

std::string describe(const Selector& s) {
  std::string out = s.quantity == "all" ? "every " : "the ";
  if (s.order) out += (s.nth > 1 ? std::to_string(s.nth) + (s.nth == 2 ? "nd " : s.nth == 3 ? "rd " : "th ") : "") +
                      *s.order + " ";
  if (s.moving) out += *s.moving ? "moving " : "parked ";
  if (s.reversing) out += "reversing ";
  if (s.color) out += *s.color + " ";
  out += s.noun.empty() ? "object" : s.noun;
  if (s.region) out += " (" + *s.region + ")";
  if (s.lane) out += " (lane: " + *s.lane + ")";
  if (s.lane_use) out += " (in the " + language::use_words(*s.lane_use) + ")";
  if (s.road_side) out += *s.road_side == "far" ? " across the road" : " on the ego's side of the road";
  if (s.beyond_use) out += " beyond the " + language::use_words(*s.beyond_use);
  if (s.junction) out += " " + *s.junction + " the junction";
  if (s.within_m) out += " within " + metres_text(*s.within_m) + " m";
  if (s.beyond_m) out += " beyond " + metres_text(*s.beyond_m) + " m";
  return out;
}

namespace {

// "everything on two wheels", "the two-wheelers": motorcycles and bicycles, each its own phrase.
Words two_wheelers_named(Words w) {
  size_t len = 0;
  const size_t at = text::find_any(w, {"everything on two wheels", "anything on two wheels", "all on two wheels",
                                       "everything with two wheels", "anything with two wheels", "two wheeled vehicles",
                                       "two wheelers", "two wheeler", "on two wheels"}, &len);
  if (at == std::string::npos) return w;
  w.erase(w.begin() + long(at), w.begin() + long(at + len));
  const Words both = text::words("all motorcycles and all bicycles");
  w.insert(w.begin() + long(at), both.begin(), both.end());
  return w;
}

// "the car by the school", "everything near the lights": a vehicle (or "everything") named before
// the thing, which only says where.
bool named_before(const Words& w, const std::string& thing) {
  const Words before(w.begin(), w.begin() + long(std::min(text::find_phrase(w, thing), w.size())));
  const auto types = lexicon::find_types(before);
  return std::any_of(types.begin(), types.end(), [](const lexicon::TypeMention& t) { return t.type.type != "object"; }) ||
         text::has_any(before, {"everything", "anything", "whatever", "all", "one", "ones", "them", "it"});
}

}  // namespace

DeletionRequest parse_deletion(const std::string& instruction) {
  const Words w = two_wheelers_named(text::words(instruction));
  DeletionRequest r;
  // A tram or a horse cannot be added, but a scene may label one (KITTI, nuScenes): what can be
  // selected is the scene's to say.
  if (auto u = lexicon::unsupported_noun(w); u && lexicon::find_types(text::words(*u)).empty() && !named_before(w, *u))
    r.unsupported = *u;
  size_t except_len = 0;
  // "every vehicle that isn't a taxi": a relative clause that negates is an exception too.
  const size_t except_at = text::find_any(w, {"except", "but not", "other than", "apart from", "besides", "but the",
                                              "excluding", "save for", "but leave", "but keep", "that isnt",
                                              "that arent", "which isnt", "which arent", "that is not", "that are not",
                                              "which is not", "which are not", "not counting"},
                                          &except_len);
  const size_t end = except_at == std::string::npos ? w.size() : except_at;
  // Skip the verb: the phrase starts after remove/delete/erase/get rid of ... Only the first verb
  // and the words right after it count: the "of" in "my side of the road" is not "rid of".
  size_t begin = 0;
  bool verb_seen = false;
  for (size_t i = 0; i < end; ++i) {
    static const char* verbs[] = {"remove", "delete", "erase", "rid", "clear", "eliminate", "take", "drop", "hide",
                                  "removes", "deletes", "erases", "away", "of"};
    const bool verb = std::find_if(std::begin(verbs), std::end(verbs), [&](const char* v) { return w[i] == v; }) !=
                      std::end(verbs);
    if (verb && (!verb_seen || i == begin)) {
      begin = i + 1;
      verb_seen = true;
    }
    if (lexicon::find_types({w[i]}).size() > 0) break;
  }
  const Selector* prev = nullptr;
  for (const auto& p : phrases(w, begin, end)) {
    if (const auto rel = split_relation(p)) {
      Selector anchor = parse_phrase(rel->reference, nullptr);
      anchor.anchor_only = true;
      anchor.quantity = "one";
      r.targets.push_back(anchor);
      Selector head = parse_phrase(rel->head, nullptr);
      head.of_previous = rel->relation;
      r.targets.push_back(head);
      prev = &r.targets.back();
      if (!r.unsupported) r.unsupported = unknown_head(rel->head);
      continue;
    }
    r.targets.push_back(parse_phrase(p, prev));
    prev = &r.targets.back();
    if (!r.unsupported) r.unsupported = unknown_head(p);
  }
  // "clear the opposite carriageway": clearing takes all it names.
  if (text::has_any(w, {"clear", "empty", "wipe"}))
    for (auto& t : r.targets)
      if (!t.order && t.quantity == "one") t.quantity = "all";
  if (r.targets.empty() && text::has_any(w, {"everything", "all"})) {
    Selector s;
    s.category = "vehicle";
    s.quantity = "all";
    r.targets.push_back(s);
  }
  if (except_at != std::string::npos)
    for (const auto& p : phrases(w, except_at + except_len, w.size())) r.except.push_back(parse_phrase(p, nullptr));
  // "everything parked on my right": people stand, they do not park.
  if (text::has_any(w, {"parked", "parking"}) &&
      std::any_of(r.targets.begin(), r.targets.end(), [](const Selector& t) { return t.category.empty(); })) {
    Selector people;
    people.category = "human";
    people.quantity = "all";
    r.except.push_back(people);
  }
  // "all vehicles except the truck": an except list implies "all".
  if (!r.except.empty())
    for (auto& t : r.targets)
      if (!t.order) t.quantity = "all";
  return r;
}

}  // namespace chatsim::agents::deletion
