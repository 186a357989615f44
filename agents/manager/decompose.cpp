#include "agents/manager/decompose.hpp"

#include <algorithm>
#include <cctype>

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"

namespace chatsim::agents::manager {
namespace {

using Words = std::vector<std::string>;
using text::has_any;

bool mentions_vehicle(const Words& w);

const std::vector<std::string>& add_verbs() {
  static const std::vector<std::string> v{"add", "adds", "put", "place", "insert", "spawn", "create", "include",
                                          "generate", "introduce", "bring", "drop", "park", "position", "there"};
  return v;
}
const std::vector<std::string>& delete_verbs() {
  static const std::vector<std::string> v{"remove", "delete", "erase", "get", "eliminate", "clear", "take", "wipe",
                                          "hide", "lose", "ditch"};
  return v;
}
bool starts_instruction(const std::string& w) {
  for (const auto* list : {&add_verbs(), &delete_verbs()})
    if (std::find(list->begin(), list->end(), w) != list->end()) return true;
  static const char* v[] = {"move", "shift", "raise", "lower", "rotate", "turn", "look", "pan", "tilt", "make",
                            "change", "modify", "set", "paint", "repaint", "respray", "recolor", "restore", "undo", "simulate", "ego", "swap", "replace"};
  for (const char* x : v)
    if (w == x) return true;
  return false;
}

// Sentences: split on . ! ? ; (not decimal points) and newlines.
std::vector<std::string> sentences(const std::string& s) {
  std::vector<std::string> out(1);
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    // "2.5 m", "ID.4": a full stop inside a word or number ends no sentence.
    const bool decimal = c == '.' && i > 0 && i + 1 < s.size() && std::isalnum(static_cast<unsigned char>(s[i - 1])) &&
                         std::isalnum(static_cast<unsigned char>(s[i + 1]));
    if ((c == '.' && !decimal) || c == '!' || c == '?' || c == ';' || c == '\n') {
      if (!out.back().empty()) out.emplace_back();
      continue;
    }
    out.back().push_back(c);
  }
  out.erase(std::remove_if(out.begin(), out.end(),
                           [](const std::string& x) { return x.find_first_not_of(" \t\r,") == std::string::npos; }),
            out.end());
  return out;
}

// After a comma, "a mercedes van parked where it was" or "the view rotated 15 degrees": a
// clause of its own although no verb starts it.
bool names_new_part(const Words& w, size_t i) {
  if (w[i] == "and" && i + 1 < w.size()) ++i;
  if (w[i] == "the" && i + 1 < w.size() && (w[i + 1] == "view" || w[i + 1] == "camera" || w[i + 1] == "viewpoint"))
    return true;
  if (w[i] != "a" && w[i] != "an" && !text::is_number_word(w[i])) return false;
  return mentions_vehicle(Words(w.begin() + long(i), w.begin() + long(std::min(w.size(), i + 5))));
}

// Clauses: a sentence split before ", and VERB", "and VERB", ", VERB", "then VERB".
std::vector<Words> clauses(const Words& w, const std::vector<bool>& comma_before) {
  std::vector<Words> out(1);
  for (size_t i = 0; i < w.size(); ++i) {
    bool split = false;
    const bool connector = w[i] == "and" || w[i] == "then" || w[i] == "also" || w[i] == "plus";
    if (connector && i + 1 < w.size()) {
      size_t j = i + 1;
      while (j < w.size() && (w[j] == "then" || w[j] == "also" || w[j] == "please" || w[j] == "finally")) ++j;
      // "... and have the ego drive slowly", "... and let it turn left": a new instruction too.
      const bool have_object = j + 1 < w.size() && (w[j] == "have" || w[j] == "let") &&
                               (w[j + 1] == "the" || w[j + 1] == "it" || w[j + 1] == "them" || w[j + 1] == "ego");
      if (j < w.size() && (starts_instruction(w[j]) || have_object || (comma_before[i] && names_new_part(w, j)))) {
        split = true;
        i = j - 1;  // drop the connector words
      }
    } else if (comma_before[i] && (starts_instruction(w[i]) || names_new_part(w, i))) {
      out.emplace_back();
    }
    if (split) {
      out.emplace_back();
      continue;
    }
    out.back().push_back(w[i]);
  }
  // Leading fillers and politeness ("could you", "please", "i want you to").
  static const char* polite[] = {"could you please", "can you please", "would you please", "could you", "can you",
                                 "would you", "will you", "i want you to", "i would like you to", "i need you to",
                                 "id like you to", "i'd like you to", "kindly", "lets", "let us", "go ahead and", "try to"};
  for (auto& c : out)
    for (bool again = true; again;) {
      again = false;
      for (const char* p : polite) {
        const auto pw = text::words(p);
        if (c.size() > pw.size() && std::equal(pw.begin(), pw.end(), c.begin())) {
          c.erase(c.begin(), c.begin() + long(pw.size()));
          again = true;
        }
      }
      if (!c.empty() && c.front() == "please") {
        c.erase(c.begin());
        again = true;
      }
    }
  for (auto& c : out) {
    while (!c.empty() && (c.front() == "additionally" || c.front() == "also" || c.front() == "then" || c.front() == "now" ||
                          c.front() == "please" || c.front() == "and" || c.front() == "finally" || c.front() == "next" ||
                          c.front() == "first" || c.front() == "lastly" || c.front() == "ok" || c.front() == "okay" ||
                          c.front() == "actually" || c.front() == "sorry" || c.front() == "wait" || c.front() == "oh" ||
                          c.front() == "hmm" || c.front() == "hey" || (c.front() == "no" && !mentions_vehicle(c))))
      c.erase(c.begin());
  }
  out.erase(std::remove_if(out.begin(), out.end(), [](const Words& c) { return c.empty(); }), out.end());
  return out;
}

bool mentions_vehicle(const Words& w) {
  for (const auto& t : lexicon::find_types(w))
    if (t.type.type != "object" && t.type.type != "pedestrian") return true;
  return !lexicon::find_brands(w).empty();
}

bool refers_to_added(const Words& w_in) {
  // "leave the bus where it is": that "it" is the bus, not something added.
  Words w = w_in;
  for (const char* p : {"where it is", "as it is", "where they are", "as they are", "where it was", "in its place"})
    for (size_t at = text::find_phrase(w, p); at != std::string::npos; at = text::find_phrase(w, p))
      w.erase(w.begin() + long(at), w.begin() + long(at + text::words(p).size()));
  return has_any(w, {"it", "its", "them", "their", "both", "they", "added", "new", "you added", "i added", "we added",
                     "inserted", "that car", "this car", "the one"});
}

// "add a porsche ahead and a mini on my left" -> two add texts; "a car stopped ahead with cones
// behind it" -> the car, then the cones placed relative to it.
std::vector<Words> split_additions(const Words& c) {
  std::vector<Words> out(1);
  for (size_t i = 0; i < c.size(); ++i) {
    if (c[i] == "with" && i + 1 < c.size() && i > 0) {
      Words rest(c.begin() + long(i) + 1, c.end());
      const auto types = lexicon::find_types(rest);
      if (!types.empty() && types.front().begin <= 2 && mentions_vehicle(Words(c.begin(), c.begin() + long(i))) &&
          types.front().type.type != "pedestrian" && types.front().type.type != "object") {
        out.emplace_back(Words{"add"});
        continue;
      }
    }
    if ((c[i] == "and" || c[i] == "plus") && i + 2 < c.size() &&
        (c[i + 1] == "a" || c[i + 1] == "an" || c[i + 1] == "another" ||
         (text::is_number_word(c[i + 1]) && c[i + 1] != "half")) &&
        c[i + 2] != "half") {
      // Only when a vehicle noun or brand follows before the next "and".
      Words rest(c.begin() + long(i) + 1, c.end());
      const auto next_and = std::find(rest.begin(), rest.end(), "and");
      if (mentions_vehicle(Words(rest.begin(), next_and))) {
        out.emplace_back(Words{"add"});
        continue;
      }
    }
    out.back().push_back(c[i]);
  }
  return out;
}

// "add a police car chasing a porsche that drives the wrong way": the chased vehicle is new
// too. It is added first, then the chaser behind it ("... chasing the porsche").
std::vector<Words> split_chase(const Words& c) {
  static const char* verbs[] = {"chasing", "chases", "following", "follows", "pursuing", "pursues", "tailing", "behind"};
  for (size_t i = 1; i + 2 < c.size(); ++i) {
    bool verb = false;
    for (const char* v : verbs) verb = verb || c[i] == v;
    if (!verb || (c[i + 1] != "a" && c[i + 1] != "an")) continue;
    const Words chased(c.begin() + long(i) + 1, c.end());
    const Words chaser(c.begin(), c.begin() + long(i));
    if (!mentions_vehicle(chased) || !mentions_vehicle(chaser)) continue;
    std::string ref;
    const auto brands = lexicon::find_brands(chased);
    const auto types = lexicon::find_types(chased);
    if (!brands.empty()) ref = text::join(chased, brands.front().begin, brands.front().end);
    else ref = text::join(chased, types.front().begin, types.front().end);
    Words first{"add"};
    first.insert(first.end(), chased.begin(), chased.end());
    Words second = chaser;
    for (const auto& w : text::words(std::string(c[i]) + " the " + ref)) second.push_back(w);
    return {first, second};
  }
  return {c};
}

// Clauses that are one thing as a whole: a restore, an abstract scene, "no parked cars", an empty
// road. False when the clause is none of these.
bool classify_whole(const Words& c, Instruction& in) {
  const std::string first = c.front();
  if (has_any(c, {"put back", "bring back", "restore", "undo the deletion", "undo the removal", "undelete",
                  "add back", "re-add", "readd", "put it back", "put them back", "undo", "add it back",
                  "add them back", "bring it back", "bring them back", "keep it", "keep that", "keep them",
                  "never mind", "nevermind"}) ||
      // "put the bus back", "bring the red car back"
      ((first == "put" || first == "bring") && c.size() > 2 && c.back() == "back")) {
    in.kind = "restore";
    in.target = in.text;
    return true;
  }
  if (has_any(c, {"traffic jam", "congestion", "gridlock", "stuck in traffic", "bumper to bumper", "jammed", "queue of",
                  "tailback", "line of cars", "backed up", "queue at", "queuing", "queueing"})) {
    in.kind = "traffic_jam";
    return true;
  }
  if (has_any(c, {"busy road", "busy street", "heavy traffic", "rush hour", "lots of traffic", "crowded road",
                  "dense traffic", "busy", "more traffic", "lot of traffic"})) {
    in.kind = "busy_road";
    return true;
  }
  // "no parked cars", "nothing parked anywhere": what should not be there is to be removed.
  if ((first == "no" || first == "nothing") && c.size() > 1 &&
      (mentions_vehicle(c) || has_any(c, {"parked", "moving", "stopped"}))) {
    in.kind = "delete";
    in.text = "remove all " + text::join(c, 1) + (mentions_vehicle(c) ? "" : " vehicles");
    return true;
  }
  if (has_any(c, {"road empty", "empty road", "empty the road", "empty street", "street empty", "no cars", "no vehicles",
                  "clear the road", "clear the street", "deserted", "without any cars", "without cars", "without vehicles",
                  "no traffic", "road clear", "street clear", "road is empty"})) {
    in.kind = "delete";
    in.text = "remove all vehicles";
    return true;
  }
  if (has_any(c, {"stopping traffic", "stopping the traffic", "stop the traffic", "stop traffic", "halting traffic",
                  "halt the traffic", "holding up traffic", "police stop", "police control"}) ||
      has_any(c, {"road block", "roadblock", "road blockade", "checkpoint", "block the road", "block off the road",
                  "block the street", "block off the street", "barricade the road", "barricade the street",
                  "police barricade", "police cordon", "cordon off"})) {
    in.kind = "road_block";
    return true;
  }
  if (has_any(c, {"construction zone", "construction site", "road work", "road works", "roadwork", "roadworks", "work zone",
                  "construction area", "lane closure", "road closure", "close the lane", "closed lane"})) {
    in.kind = "construction_zone";
    return true;
  }
  return false;
}

// "a navy suv should be added 40 m ahead", "i want a van placed behind me": the passive of an
// addition said in the active ("add a navy suv 40 m ahead"). The words unchanged otherwise.
Words active_addition(const Words& c) {
  static const char* participles[] = {"added", "placed", "put", "inserted", "spawned", "created", "included",
                                      "introduced", "positioned", "dropped", "generated"};
  for (size_t i = 1; i < c.size(); ++i) {
    if (std::none_of(std::begin(participles), std::end(participles), [&](const char* p) { return c[i] == p; })) continue;
    const bool be = c[i - 1] == "be" || c[i - 1] == "been" || c[i - 1] == "being" || c[i - 1] == "get" || c[i - 1] == "is" ||
                    c[i - 1] == "are";
    // "want a van placed": a vehicle noun right before, not "the car i added" nor "the added car".
    const Words head(c.begin(), c.begin() + long(i));
    // "the added car should be placed ahead", "it should be put behind": a revision, not new.
    if (has_any(head, {"the", "that", "this", "it", "them", "they", "its"})) continue;
    const auto types = lexicon::find_types(head);
    const bool wanted = !types.empty() && types.back().end == i && has_any(c, {"want", "need", "like", "have", "get"});
    if (!be && !wanted) continue;
    size_t from = i;
    while (from > 0 && (c[from - 1] == "be" || c[from - 1] == "been" || c[from - 1] == "being" || c[from - 1] == "get" ||
                        c[from - 1] == "is" || c[from - 1] == "are" || c[from - 1] == "should" || c[from - 1] == "must" ||
                        c[from - 1] == "shall" || c[from - 1] == "will" || c[from - 1] == "would" || c[from - 1] == "to" ||
                        c[from - 1] == "needs" || c[from - 1] == "has" || c[from - 1] == "have"))
      --from;
    Words out{"add"};
    size_t start = 0;
    // "i want / we need / i'd like ... a van placed": the wish goes too.
    for (size_t k = 0; k < from; ++k)
      if (c[k] == "a" || c[k] == "an" || c[k] == "some" || c[k] == "another" || text::is_number_word(c[k]) ||
          lexicon::find_types(Words(c.begin() + long(k), c.begin() + long(from))).size() > 0) {
        start = k;
        break;
      }
    out.insert(out.end(), c.begin() + long(start), c.begin() + long(from));
    out.insert(out.end(), c.begin() + long(i) + 1, c.end());
    return out;
  }
  return c;
}

// "a pickup should come out of the side street": a vehicle named with "a" as the subject is new.
bool indefinite_vehicle_subject(const Words& c) {
  if (c.size() < 2 || !(c[0] == "a" || c[0] == "an" || c[0] == "another" || (text::is_number_word(c[0]) && c[0] != "half")))
    return false;
  if (c[1] == "of" || c[1] == "bit" || c[1] == "little") return false;  // "one of the cars", "a bit further"
  const auto types = lexicon::find_types(c);
  const auto brands = lexicon::find_brands(c);
  const bool vehicle_type = !types.empty() && types.front().type.type != "pedestrian";
  const size_t noun = std::min(vehicle_type ? types.front().begin : c.size(), brands.empty() ? c.size() : brands.front().begin);
  return noun >= 1 && noun <= 4 && noun < c.size();  // "2 m forward": the number itself is no model name
}

Instruction classify(const Words& c_in) {
  const Words c = active_addition(c_in);
  Instruction in;
  in.text = text::join(c);
  const std::string first = c.front();
  auto starts = [&](const std::vector<std::string>& verbs) {
    return std::find(verbs.begin(), verbs.end(), first) != verbs.end();
  };
  if (classify_whole(c, in)) return in;
  const bool vehicle = mentions_vehicle(c);
  const bool added_ref = refers_to_added(c);
  // "I'd like the bus gone", "I want the red car removed", "I don't want the van in the shot": a
  // deletion said by its result.
  if (vehicle && !starts(add_verbs()) &&
      has_any(c, {"gone", "removed", "deleted", "erased", "out of the way", "out of the picture", "out of the scene",
                  "out of the shot", "out of shot", "don't want", "dont want", "do not want", "don't need",
                  "do not need", "no longer want", "not want"})) {
    in.kind = added_ref ? "remove_added" : "delete";
    in.target = added_ref ? in.text : "";
    in.text = "remove " + in.text;
    return in;
  }
  // "get it to drive off" is a revision; "get rid of it", "get the bus out of here" a deletion.
  const bool causative_get = first == "get" && !has_any(c, {"get rid", "out", "away", "off the road", "gone"});
  if ((starts(delete_verbs()) && !causative_get) || has_any(c, {"get rid of", "take away", "take out"})) {
    in.kind = added_ref ? "remove_added" : "delete";
    in.target = added_ref ? in.text : "";
    return in;
  }
  if (has_any(c, {"dangerous", "cut in", "cuts in", "cutting in", "cut off", "cuts off", "cutting me off"}) &&
      !starts(add_verbs())) {
    in.kind = "add";
    std::string t = in.text;
    if (!vehicle) t += " car";
    if (!has_any(c, {"cut in", "cuts in", "cutting in", "cut off", "cutting me off", "cuts off"})) t += " cutting in";
    if (!has_any(c, {"left", "right"})) t += " left front";
    in.text = t;
    return in;
  }
  if (indefinite_vehicle_subject(c) && !has_any(c, {"what", "why", "how", "who", "which"})) {
    in.kind = "add";
    return in;
  }
  // "another one behind that", "one more on the left": a copy of the vehicle spoken about last.
  if ((first == "another" || (c.size() > 1 && first == "one" && c[1] == "more")) && !vehicle) {
    in.kind = "add";
    in.target = "it";
    in.text = "add " + in.text;
    return in;
  }
  if (starts(add_verbs())) {
    // "add a flying saucer above the bus": what is to be added is no vehicle, whatever follows.
    const auto bad = lexicon::unsupported_noun(c);
    const auto types = lexicon::find_types(c);
    if (bad && (types.empty() || text::find_phrase(c, *bad) < types.front().begin)) {
      in.kind = "unclear";
      in.target = *bad;
      return in;
    }
  }
  if (starts(add_verbs()) && (vehicle || has_any(c, {"another", "one more", "one"}))) {
    in.kind = "add";
    if (has_any(c, {"another", "one more", "another one", "same", "similar"}) &&
        !mentions_vehicle(Words(c.begin() + 1, c.end())))
      in.target = "it";
    return in;
  }
  // "look behind", "turn around": with no vehicle named, the view turns.
  const bool view_idiom = !vehicle && !added_ref &&
                          has_any(c, {"look behind", "look back", "look backward", "look backwards", "turn around",
                                      "face backward", "face backwards", "look the other way", "face the other way"});
  const bool view_words = has_any(c, {"view", "camera", "viewpoint", "perspective", "vantage", "ego", "point of view"}) ||
                          has_any(c, {"i drive", "we drive", "drive ahead", "drives ahead"}) || view_idiom;
  const bool revise_verb = has_any(c, {"make", "change", "modify", "let", "have", "get", "set", "paint", "repaint", "respray", "recolor", "color", "turn",
                                       "move", "speed", "slow", "swap", "replace", "switch", "should", "park", "stop",
                                       "pull", "reverse", "accelerate", "brake"});
  // "the white one", "the second one": a vehicle named by what tells it apart.
  const bool one_ref = has_any(c, {"one", "ones"}) && !starts(add_verbs());
  // "change the colour to green", "set the speed to 30 km/h": what is changed names no vehicle.
  const bool attribute_ref = has_any(c, {"the color", "its color", "the paint", "the speed", "its speed", "the brand",
                                         "the model", "the make", "the lane", "its lane"});
  if (!view_words && (added_ref || vehicle || one_ref || attribute_ref) && revise_verb) {
    in.kind = "revise";
    in.target = reference_in(in.text);
    return in;
  }
  if (view_words || has_any(c, {"move", "shift", "raise", "lower", "rotate", "look", "pan", "tilt", "turn", "go", "slide", "nudge"})) {
    const auto w = c;
    const bool has_amount = !text::quantities(w, {"meters", "meter", "m", "degrees", "degree", "feet", "ft", "cm"}).empty();
    if (view_words || has_amount) {
      in.kind = "view";
      return in;
    }
  }
  if (vehicle && !has_any(c, {"what", "why", "how", "who"})) {
    in.kind = "add";
    return in;
  }
  // "2 m forward", "another 10 degrees left": an amount and a direction with nothing else named
  // moves the view.
  if (!text::quantities(c, {"meters", "meter", "m", "degrees", "degree", "cm", "feet", "ft"}).empty() &&
      has_any(c, {"forward", "ahead", "back", "backward", "left", "right", "up", "down", "higher", "lower"})) {
    in.kind = "view";
    return in;
  }
  in.kind = "unclear";
  return in;
}

// "an ambulance and two police cars rushing toward me": a part that ends with its noun takes the
// words that follow the next part's noun (how and where they all go).
void share_trailing_words(std::vector<Words>& parts) {
  for (size_t k = parts.size(); k-- > 1;) {
    const auto own = lexicon::find_types(parts[k - 1]);
    const auto next = lexicon::find_types(parts[k]);
    if (own.empty() || next.empty() || own.back().end != parts[k - 1].size()) continue;
    parts[k - 1].insert(parts[k - 1].end(), parts[k].begin() + long(next.front().end), parts[k].end());
  }
}

}  // namespace

std::string reference_in(const std::string& clause) {
  const Words w = text::words(clause);
  // "make it chase the red car": the object right after the verb is what changes.
  if (w.size() > 1 && (w[1] == "it" || w[1] == "them") &&
      (w[0] == "make" || w[0] == "have" || w[0] == "let" || w[0] == "turn" || w[0] == "move" || w[0] == "park" ||
       w[0] == "change" || w[0] == "paint" || w[0] == "repaint" || w[0] == "respray" || w[0] == "recolor" ||
       w[0] == "color" || w[0] == "set"))
    return w[1];
  if (text::has_any(w, {"both of them", "both", "all of them", "them", "they", "all the added", "all added", "each of them"}))
    return text::has_any(w, {"both"}) ? "both" : "them";
  // "the added car", "the porsche", "the police car", "the porsche i added"
  for (size_t i = 0; i < w.size(); ++i) {
    if (w[i] != "the" && w[i] != "that" && w[i] != "this") continue;
    size_t j = i + 1;
    while (j < w.size() && (w[j] == "added" || w[j] == "new" || w[j] == "first" || w[j] == "second" || w[j] == "third" ||
                            w[j] == "last" || lexicon::is_color_word(w[j]) || w[j] == "dark" || w[j] == "light"))
      ++j;
    const Words rest(w.begin() + long(j), w.end());
    const auto types = lexicon::find_types(rest);
    const auto brands = lexicon::find_brands(rest);
    size_t end = j;
    if (!brands.empty() && brands.front().begin == 0) end = j + brands.front().end;
    if (!types.empty() && types.front().begin == end - j) end = j + types.front().end;
    if (end > j || j > i + 1) {
      while (end < w.size() && (w[end] == "i" || w[end] == "we" || w[end] == "you" || w[end] == "added" || w[end] == "just"))
        ++end;
      return text::join(w, i, end);
    }
  }
  return "it";  // "it", "its", or nothing said: the vehicle spoken about last
}

std::vector<Instruction> decompose(const std::string& command) {
  std::vector<Instruction> out;
  for (const auto& sentence : sentences(command)) {
    // Words plus which ones had a comma before them.
    Words w;
    std::vector<bool> comma;
    bool pending_comma = false;
    std::string cur;
    for (size_t i = 0; i <= sentence.size(); ++i) {
      const char ch = i < sentence.size() ? sentence[i] : ' ';
      if (ch == ',' || ch == ':') {
        const auto ws = text::words(cur);
        for (size_t k = 0; k < ws.size(); ++k) {
          w.push_back(ws[k]);
          comma.push_back(k == 0 && pending_comma);
        }
        cur.clear();
        pending_comma = true;
        continue;
      }
      cur.push_back(ch);
    }
    const auto ws = text::words(cur);
    for (size_t k = 0; k < ws.size(); ++k) {
      w.push_back(ws[k]);
      comma.push_back(k == 0 && pending_comma);
    }
    lexicon::correct_typos(w);
    std::string previous;
    for (const auto& c : clauses(w, comma)) {
      Instruction in = classify(c);
      // "raise the camera 2 m and move it 1 m left": "it" is the camera of the clause before.
      if (in.kind == "revise" && previous == "view" && !mentions_vehicle(c) &&
          !text::quantities(c, {"meters", "meter", "m", "degrees", "degree", "feet", "ft", "cm"}).empty()) {
        in.kind = "view";
        in.target.clear();
      }
      previous = in.kind;
      if (in.kind == "add") {
        std::vector<Words> parts;
        for (const auto& part : split_additions(text::words(in.text)))
          for (const auto& p : split_chase(part)) parts.push_back(p);
        share_trailing_words(parts);
        if (parts.size() > 1) {
          for (const auto& p : parts) {
            Instruction part = in;
            part.text = text::join(p);
            out.push_back(part);
          }
          continue;
        }
      }
      out.push_back(in);
    }
  }
  return out;
}

nlohmann::json to_json(const std::vector<Instruction>& instructions) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& i : instructions) {
    nlohmann::json j{{"kind", i.kind}, {"text", i.text}};
    if (!i.target.empty()) j["target"] = i.target;
    if (i.count != 1) j["count"] = i.count;
    list.push_back(j);
  }
  return {{"instructions", list}};
}

std::vector<Instruction> instructions_from_json(const nlohmann::json& j) {
  std::vector<Instruction> out;
  for (const auto& i : j.value("instructions", nlohmann::json::array()))
    out.push_back({i.value("kind", "unclear"), i.value("text", ""), i.value("target", ""), i.value("count", 1)});
  return out;
}

}  // namespace chatsim::agents::manager
