// What one clause of a command is: an addition, deletion, revision, view change, restore, an
// abstract scene, or unclear (the offline interpreter's part of the manager).
#include "agents/manager/classify.hpp"

#include <algorithm>

#include "agents/language/lane_names.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"

namespace chatsim::agents::manager::detail {

using Words = std::vector<std::string>;
using text::has_any;

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

bool mentions_vehicle(const Words& w) {
  for (const auto& t : lexicon::find_types(w))
    if (t.type.type != "object" && !t.type.living()) return true;
  return !lexicon::find_brands(w).empty();
}

bool says_amount(const Words& w, bool angles) {
  static const std::vector<std::string_view> kWithAngles = [] {
    auto units = text::length_units();
    units.insert(units.end(), {"degrees", "degree"});
    return units;
  }();
  return !text::quantities(w, angles ? kWithAngles : text::length_units()).empty();
}

namespace {

// A correction said without a verb, as the revision of what was spoken of last.
Instruction revises_last(const std::string& text) {
  Instruction in;
  in.kind = "revise";
  in.target = "it";
  in.text = text;
  return in;
}

bool refers_to_added(const Words& w_in) {
  // "leave the bus where it is": that "it" is the bus, not something added.
  Words w = w_in;
  std::vector<std::string> phrases{"where it is", "as it is", "where they are", "as they are"};
  for (const auto& p : lexicon::place_of_removed_phrases()) phrases.push_back(p);
  for (const auto& p : phrases)
    for (size_t at = text::find_phrase(w, p); at != std::string::npos; at = text::find_phrase(w, p))
      w.erase(w.begin() + long(at), w.begin() + long(at + text::words(p).size()));
  return has_any(w, {"it", "its", "them", "their", "both", "they", "added", "new", "you added", "i added", "we added",
                     "inserted", "that car", "this car", "the one", "make that", "make this"});
}

// Clauses that are one thing as a whole: a restore, an abstract scene, "no parked cars", an empty
// road. False when the clause is none of these.
bool classify_whole(const Words& c, Instruction& in) {
  const std::string first = c.front();
  // "a green one instead", "a Jeep instead": what was just added, said again differently.
  if ((first == "a" || first == "an") && has_any(c, {"instead", "rather"}) &&
      (has_any(c, {"one"}) || mentions_vehicle(c)) && !has_any(c, {"where", "in its place", "of the", "there"})) {
    Words said;
    for (const auto& x : c)
      if (x != "instead" && x != "rather") said.push_back(x);
    in.kind = "revise";
    in.target = "it";
    in.text = "make it " + text::join(said);
    return true;
  }
  // "undo that", "scratch that": the whole last round, whatever it did ("undo the deletion" is a
  // restore, below).
  const bool of_deletion = has_any(c, {"deletion", "deletions", "removal", "delete", "deleted", "removed", "remove"});
  if (!of_deletion && (first == "undo" || first == "revert" ||
                       has_any(c, {"scratch that", "cancel that", "take that back", "forget that", "go back a step",
                                   "go back one step", "revert that", "revert the last"}))) {
    in.kind = "undo";
    return true;
  }
  if (has_any(c, {"put back", "bring back", "restore", "undo the deletion", "undo the removal", "undelete",
                  "add back", "re-add", "readd", "put it back", "put them back", "undo", "add it back",
                  "add them back", "bring it back", "bring them back", "keep it", "keep that", "keep them",
                  "never mind", "nevermind"}) ||
      // "keep the black ones (though)", "spare the bus": after a deletion, those come back.
      ((first == "keep" || first == "spare") && c.size() > 1 && c[1] != "going" && c[1] != "driving" &&
       c[1] != "moving") ||
      // "put the bus back", "bring the red car back"; not "put it 20 m further back" (a move)
      ((first == "put" || first == "bring") && c.size() > 2 && c.back() == "back" &&
       !has_any(c, {"further", "farther", "more"}) &&
       !says_amount(c, false))) {
    in.kind = "restore";
    in.target = in.text;
    return true;
  }
  // "remove both cars queuing to turn left", "remove everything in the closed lane", "remove the
  // roadworks sign": a removal builds no scene (what follows says which vehicles, or names a thing).
  const bool removes = has_any({first}, {"remove", "delete", "erase", "eliminate", "wipe", "ditch"}) ||
                       text::find_phrase(c, "get rid of") == 0;
  if (removes) return false;
  if (const auto cleared = cleared_place(c)) {  // "empty the drive-thru", "clear the queue at the barrier"
    in = Instruction{"delete", *cleared, "", 1};
    return true;
  }
  const bool joins_queue = has_any(c, {"back of the", "end of the"}) && has_any(c, {"queue", "line"});  // not a jam
  if (!joins_queue && has_any(c, {"traffic jam", "jam", "jams", "standstill", "stop and go", "congested", "congestion",
                                  "gridlock", "stuck in traffic", "bumper to bumper", "jammed", "queue of", "tailback",
                                  "line of cars", "backed up", "queue at", "queuing", "queueing"})) {
    in.kind = "traffic_jam";
    return true;
  }
  // "make the traffic heavy on the branch road": traffic with a word of density anywhere in the clause.
  const bool dense_traffic =
      has_any(c, {"traffic"}) &&
      has_any(c, {"heavy", "heavier", "dense", "denser", "busier", "thick", "thicker", "crowded", "packed", "intense"});
  if (dense_traffic || has_any(c, {"busy road", "busy street", "heavy traffic", "rush hour", "lots of traffic",
                                   "crowded road", "dense traffic", "busy", "more traffic", "lot of traffic", "the rush",
                                   "lunchtime rush", "lunch rush", "morning rush", "evening rush", "peak hour",
                                   "peak time", "hectic", "heaving", "chaotic", "swamped"})) {
    in.kind = "busy_road";
    // "a busy Saturday at the gas station", "the car park is busy": a place to stop at, full of
    // parked cars (not "busy with traffic": cars driving there).
    const auto area = language::find_lane_name(c);
    if (area && (area->use == "car_park" || area->use == "lay_by" || area->use == "fuel_station") &&
        !has_any(c, {"traffic", "driving", "moving", "cars coming", "coming and going"})) {
      in.kind = "add";
      in.text = "add a few cars parked at the " + text::join(c, area->begin, area->end);
    }
    return true;
  }
  // "no parked cars", "nothing parked anywhere": what should not be there is to be removed.
  if ((first == "no" || first == "nothing") && c.size() > 1 && !bare_place(c) &&
      (mentions_vehicle(c) || has_any(c, {"parked", "moving", "stopped"}))) {
    in.kind = "delete";
    in.text = "remove all " + text::join(c, 1) + (mentions_vehicle(c) ? "" : " vehicles");
    return true;
  }
  // "empty the whole scene of vehicles", "clear the car park of trucks": all of those go; "clear
  // the whole scene": every vehicle (a lane or place to clear stays a deletion there).
  if ((first == "empty" || first == "clear" || first == "clean") && c.size() > 1) {
    const size_t of = text::find_phrase(c, "of");
    const Words after_of = of == std::string::npos ? Words{} : Words(c.begin() + long(of) + 1, c.end());
    if (mentions_vehicle(after_of) || has_any(after_of, {"traffic", "everything", "anything"})) {
      in.kind = "delete";
      in.text = mentions_vehicle(after_of) ? "remove all " + text::join(after_of) : "remove all vehicles";
      // "clear the left side of parked cars", "clear the car park of trucks": where stays said.
      const Words place(c.begin() + 1, c.begin() + long(of));
      const bool everywhere = std::all_of(place.begin(), place.end(), [](const std::string& x) {
        return x == "the" || x == "whole" || x == "entire" || x == "scene" || x == "road" || x == "street" ||
               x == "picture" || x == "frame" || x == "view" || x == "area";
      });
      if (!everywhere) in.text += (has_any(place, {"side"}) ? " on " : " in ") + text::join(place);
      return true;
    }
    if (!mentions_vehicle(c) && has_any(c, {"scene", "whole", "entire", "everything", "picture", "frame", "view"})) {
      in.kind = "delete";
      in.text = "remove all vehicles";
      // "clear everything coming the other way": every vehicle that does what follows.
      const size_t every = text::find_any(c, {"everything", "anything"});
      if (every != std::string::npos && every + 1 < c.size() &&
          !has_any(Words(c.begin() + long(every) + 1, c.end()), {"scene", "picture", "frame", "view", "shot"}))
        in.text += " " + text::join(c, every + 1);
      return true;
    }
  }
  // "I need the forecourt empty", "I want the drop-off lane clear": a place said to be empty.
  static const char* kEmpty[] = {"empty", "clear", "cleared", "emptied", "deserted"};
  const auto place_from = c.end() - long(std::min<size_t>(c.size(), 6));
  if (c.size() >= 3 && !mentions_vehicle(c) &&
      std::any_of(std::begin(kEmpty), std::end(kEmpty), [&](const char* e) { return c.back() == e; }) &&
      std::find(place_from, c.end() - 2, "the") != c.end() - 2) {
    in.kind = "delete";
    in.text = "remove all vehicles";
    if (const auto lane = language::find_lane_name(c)) in.text += " in the " + text::join(c, lane->begin, lane->end);
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
                  "halt the traffic", "holding up traffic", "police stop", "police control", "controlling traffic",
                  "controlling the traffic", "directing traffic", "directing the traffic", "accident scene",
                  "crash scene", "scene of an accident", "scene of a crash"}) ||
      has_any(c, {"road block", "roadblock", "road blockade", "checkpoint", "block the road", "block off the road",
                  "block the street", "block off the street", "barricade the road", "barricade the street",
                  "police barricade", "police cordon", "cordon off"})) {
    in.kind = "road_block";
    return true;
  }
  // "add a police car in the closed lane", "the van past the roadworks": works already there
  // ("the ...") are a place, not a zone to build.
  const size_t works = text::find_any(c, {"construction zone", "construction site", "road work", "road works",
                                          "roadwork", "roadworks", "work zone", "construction area", "lane closure",
                                          "road closure", "close the lane", "closed lane"});
  if (works != std::string::npos && (works == 0 || c[works - 1] != "the")) {
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
    // "i want / we need / i'd like ... a van placed": the wish goes too; the vehicle starts at its
    // article or number, else at its noun.
    size_t start = std::string::npos;
    for (size_t k = 0; k < from && start == std::string::npos; ++k)
      if (c[k] == "a" || c[k] == "an" || c[k] == "some" || c[k] == "another" || text::is_number_word(c[k])) start = k;
    if (start == std::string::npos) {
      const auto nouns = lexicon::find_types(Words(c.begin(), c.begin() + long(from)));
      start = nouns.empty() ? 0 : nouns.front().begin;
    }
    out.insert(out.end(), c.begin() + long(start), c.begin() + long(from));
    out.insert(out.end(), c.begin() + long(i) + 1, c.end());
    return out;
  }
  return c;
}

// "the red car behind us - delete it", "the bus, remove it": a topic named first, then the verb
// with "it". Said the usual way round ("delete the red car behind us"); unchanged otherwise.
Words topic_first(const Words& c) {
  if (c.size() < 4 || (c[0] != "the" && c[0] != "that" && c[0] != "this" && c[0] != "those" && c[0] != "these"))
    return c;
  for (size_t v = 2; v + 1 < c.size(); ++v) {
    const bool verb = std::find(delete_verbs().begin(), delete_verbs().end(), c[v]) != delete_verbs().end() ||
                      c[v] == "make" || c[v] == "paint" || c[v] == "change" || c[v] == "move";
    if (!verb || (c[v + 1] != "it" && c[v + 1] != "them")) continue;
    if (!mentions_vehicle(Words(c.begin(), c.begin() + long(v)))) return c;
    Words out{c[v]};
    out.insert(out.end(), c.begin(), c.begin() + long(v));
    out.insert(out.end(), c.begin() + long(v) + 2, c.end());
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
  const bool vehicle_type = !types.empty() && !types.front().type.living();
  const size_t noun = std::min(vehicle_type ? types.front().begin : c.size(), brands.empty() ? c.size() : brands.front().begin);
  return noun >= 1 && noun <= 4 && noun < c.size();  // "2 m forward": the number itself is no model name
}

// "add another behind the cab": the words right after "another" (up to a place word) name no
// vehicle, so it is another of the last one ("another red one" too, recoloured); "add another
// cab behind it" names its own.
bool names_its_own_kind(const Words& c) {
  size_t at = text::find_any(c, {"another", "one more", "same", "similar"});
  if (at == std::string::npos) {  // "add a red one in front of the truck": the words before "one"
    const auto one = std::find(c.begin(), c.end(), "one");
    return mentions_vehicle(Words(c.begin() + 1, one));
  }
  size_t end = at + 1;
  static const char* kPlaceWords[] = {"behind", "in", "on", "at", "ahead", "next", "beside", "to", "near", "parked",
                                      "driving", "following", "after", "before", "just", "right", "left", "coming"};
  while (end < c.size() && std::none_of(std::begin(kPlaceWords), std::end(kPlaceWords),
                                        [&](const char* p) { return c[end] == p; }))
    ++end;
  const Words own(c.begin() + long(at) + 1, c.begin() + long(end));
  return mentions_vehicle(own);
}

bool starts_with(const Words& c, const std::vector<std::string>& verbs) {
  return std::find(verbs.begin(), verbs.end(), c.front()) != verbs.end();
}

// A deletion, said by its verb or its result ("I'd like the bus gone").
bool classify_deletion(const Words& c, bool vehicle, bool added_ref, Instruction& in) {
  const std::string& first = c.front();
  // "I'd like the bus gone", "I want the red car removed", "I don't want the van in the shot",
  // "what if the bus wasn't there?": a deletion said by its result.
  const bool everything = has_any(c, {"everything", "anything", "every vehicle", "all the vehicles", "all vehicles"});
  if ((vehicle || everything) && !starts_with(c, add_verbs()) &&
      has_any(c, {"gone", "removed", "deleted", "erased", "out of the way", "out of the picture", "out of the scene",
                  "out of the shot", "out of shot", "don't want", "dont want", "do not want", "don't need",
                  "rather not have", "rather not see", "prefer not to have", "prefer not to see",
                  "do not need", "no longer want", "not want", "has to go", "have to go", "must go", "should go",
                  "needs to go", "can go", "got to go", "has got to go", "wasnt there", "werent there",
                  "was not there", "were not there", "wasnt here", "werent here", "not there anymore", "didnt exist",
                  "did not exist", "disappeared", "vanished"})) {
    in.kind = added_ref ? "remove_added" : "delete";
    in.target = added_ref ? in.text : "";
    in.text = "remove " + in.text;
    return true;
  }
  // "what would it look like without the red bus?", "show me the street without the parked cars":
  // what it should be without is to be removed.
  if (const size_t at = text::find_phrase(c, "without"); vehicle && !starts_with(c, add_verbs()) &&
      at != std::string::npos && at + 2 < c.size() &&
      (c[at + 1] == "the" || c[at + 1] == "that" || c[at + 1] == "those" || c[at + 1] == "any" || c[at + 1] == "all")) {
    in.kind = "delete";
    in.text = "remove " + text::join(c, at + 1);
    return true;
  }
  // "get it to drive off" is a revision; "get rid of it", "get the bus out of here" a deletion.
  const bool causative_get = first == "get" && !has_any(c, {"get rid", "out", "away", "off the road", "gone"});
  // "take the camera 5 m back": a view moved with a verb that otherwise deletes.
  const bool moves_view = !vehicle && has_any(c, {"camera", "view", "viewpoint"});
  if ((starts_with(c, delete_verbs()) && !causative_get && !moves_view) ||
      has_any(c, {"get rid of", "take away", "take out"})) {
    in.kind = added_ref ? "remove_added" : "delete";
    in.target = added_ref ? in.text : "";
    return true;
  }
  return false;
}

// An addition: by its verb, a new subject ("a pickup should come out..."), a copy ("another
// one"), or a dangerous cut-in. A named thing that cannot be added is unclear, with the thing.
bool classify_addition(const Words& c, bool vehicle, Instruction& in) {
  const std::string& first = c.front();
  const bool add_verb = starts_with(c, add_verbs());
  // "place the viewpoint one lane to the right": the view is placed, nothing is added.
  if (!vehicle && has_any(c, {"camera", "view", "viewpoint"})) return false;
  if (has_any(c, {"dangerous", "cut in", "cuts in", "cutting in", "cut off", "cuts off", "cutting me off"}) && !add_verb) {
    in.kind = "add";
    std::string t = in.text;
    if (!vehicle) t += " car";
    if (!has_any(c, {"cut in", "cuts in", "cutting in", "cut off", "cutting me off", "cuts off"})) t += " cutting in";
    if (!has_any(c, {"left", "right"})) t += " left front";
    in.text = t;
    return true;
  }
  if (indefinite_vehicle_subject(c) && !has_any(c, {"what", "why", "how", "who", "which"})) {
    in.kind = "add";
    return true;
  }
  // "another one behind that", "one more on the left", "a grey one behind it": a copy of the
  // vehicle spoken about last.
  const size_t article = add_verb ? 1 : 0;  // "add a white one behind it" as well
  const auto one_at = std::find(c.begin(), c.end(), "one");
  const bool described_one = c.size() > article && (c[article] == "a" || c[article] == "an") && one_at != c.end() &&
                             one_at - c.begin() <= long(article) + 3 &&
                             std::all_of(c.begin() + long(article) + 1, one_at, [](const std::string& x) {
                               return lexicon::is_color_word(x) || x == "dark" || x == "light" || x == "bright" ||
                                      x == "new" || x == "similar" || x == "bigger" || x == "smaller" ||
                                      x == "second" || x == "third" || x == "fourth" || x == "further";
                             });
  if ((first == "another" || (c.size() > 1 && first == "one" && c[1] == "more") || described_one) &&
      !names_its_own_kind(c)) {
    in.kind = "add";
    in.target = "it";
    if (!add_verb) in.text = "add " + in.text;
    return true;
  }
  if (!add_verb) return false;
  // "put it behind the grey car", "place them on the left": what is there already is moved.
  if (c.size() > 1 && (c[1] == "it" || c[1] == "them" || c[1] == "that" || c[1] == "this")) return false;
  // "add a flying saucer above the bus": what is to be added is no vehicle, whatever follows.
  const auto bad = lexicon::unsupported_noun(c);
  const auto types = lexicon::find_types(c);
  if (bad && (types.empty() || text::find_phrase(c, *bad) <= types.front().begin)) {
    in.kind = "unclear";
    in.target = *bad;
    return true;
  }
  // "add a pedestrian pushing a trolley": the first thing named is what is added, and a walker is no
  // vehicle. In "a horse box trailer" the horse only says what kind of trailer.
  const auto qualifies_next = [&](const lexicon::TypeMention& t) {
    return std::any_of(types.begin(), types.end(), [&](const lexicon::TypeMention& v) {
      return v.begin > t.begin && v.begin <= t.begin + 2 && v.type.addable();
    });
  };
  const auto head = std::find_if(types.begin(), types.end(), [&](const lexicon::TypeMention& t) {
    return t.type.type != "object" && !qualifies_next(t);
  });
  if (head != types.end() && !head->type.addable()) {
    in.kind = "unclear";
    in.target = text::join(c, head->begin, head->end);
    return true;
  }
  // "add a black zorblax at the front": a name the vocabulary lacks where a vehicle belongs is a
  // car of unknown make (the asset agent says so), not a command not understood.
  if (vehicle || has_any(c, {"another", "one more", "one"}) || lexicon::unknown_vehicle_name(c, 1)) {
    in.kind = "add";
    if (has_any(c, {"another", "one more", "another one", "same", "similar"}) && !names_its_own_kind(c)) in.target = "it";
    return true;
  }
  return false;
}

}  // namespace

Instruction classify(const Words& c_in) {
  Words c = causative_addition(topic_first(active_addition(c_in)));
  Instruction in;
  in.text = text::join(c);
  if (classify_whole(c, in)) return in;
  c = existing_one(fill_addition(c));  // not "fill the far side with heavy traffic" (a busy road, above)
  in.text = text::join(c);
  // "slower", "a bit closer", "in front of the bendy bus", "behind it": a change or a place said
  // alone revises what was spoken of last.
  if (const auto meant = meant_correction(c)) return revises_last(*meant);
  if (const auto change = bare_change(c)) return revises_last("make it " + *change);
  if (const auto place = bare_place(c)) return revises_last("put it " + *place);
  const bool vehicle = mentions_vehicle(c);
  const bool added_ref = refers_to_added(c);
  if (classify_deletion(c, vehicle, added_ref, in) || classify_addition(c, vehicle, in)) return in;
  const bool add_verb = starts_with(c, add_verbs());
  // "look behind", "turn around": with no vehicle named, the view turns.
  const bool view_idiom = !vehicle && !added_ref &&
                          has_any(c, {"look behind", "look back", "look backward", "look backwards", "turn around",
                                      "face backward", "face backwards", "look the other way", "face the other way",
                                      "look left", "look right", "look to the left", "look to the right", "face left",
                                      "face right"});
  // "I want to see it from the other lane": "it" is the scene, not an added vehicle.
  const bool seen_from = !vehicle && has_any(c, {"look from", "looking from", "seen from", "see from", "see it from",
                                                 "see this from", "see that from", "see everything from",
                                                 "watch from", "watch it from", "view it from", "show it from"});
  // "drive a lot faster", "crawl along slowly": an order to drive, with no vehicle to drive, is the ego's.
  const bool ego_drives = !vehicle && !added_ref && c.size() > 1 &&
                          has_any({c.front()}, {"drive", "go", "speed", "crawl", "cruise", "roll"}) &&
                          has_any(c, {"faster", "slower", "slowly", "quickly", "fast", "slow", "speed up", "slow down"});
  // "shift us one lane left", "move me up 2 m": we are where the cameras are.
  bool moves_us = false;
  for (size_t i = 0; i + 1 < c.size() && !vehicle && !added_ref; ++i)
    moves_us = moves_us || (has_any({c[i]}, {"move", "shift", "slide", "nudge", "take", "put", "bring", "lift", "raise",
                                             "lower", "drop", "place", "position", "pull", "push"}) &&
                            has_any({c[i + 1]}, {"us", "me", "ourselves", "myself"}));
  const bool view_words = has_any(c, {"view", "camera", "viewpoint", "perspective", "vantage", "ego", "point of view"}) ||
                          has_any(c, {"i drive", "we drive", "drive ahead", "drives ahead"}) || view_idiom || seen_from ||
                          ego_drives || moves_us;
  const bool revise_verb = has_any(c, {"make", "change", "modify", "let", "have", "get", "set", "put", "place", "position",
                                       "push", "paint", "repaint", "respray", "recolor", "color", "turn",
                                       "move", "speed", "slow", "swap", "replace", "switch", "should", "park", "stop",
                                       "pull", "reverse", "accelerate", "brake"});
  // "the white one", "the second one": a vehicle named by what tells it apart.
  const bool one_ref = has_any(c, {"one", "ones"}) && !add_verb;
  // "change the colour to green", "set the speed to 30 km/h": what is changed names no vehicle.
  const bool attribute_ref = has_any(c, {"the color", "its color", "the paint", "the speed", "its speed", "the brand",
                                         "the model", "the make", "the lane", "its lane"});
  if (!view_words && (added_ref || vehicle || one_ref || attribute_ref) && revise_verb) {
    in.kind = "revise";
    in.target = reference_in(in.text);
    return in;
  }
  const bool has_amount = says_amount(c);
  if (view_words ||
      (has_amount && has_any(c, {"move", "shift", "raise", "lower", "rotate", "look", "pan", "tilt", "turn", "go", "slide",
                                 "nudge", "drop", "lift", "step", "swing", "yaw", "bring"}))) {
    in.kind = "view";
    return in;
  }
  if (vehicle && !has_any(c, {"what", "why", "how", "who"})) {
    in.kind = "add";
    return in;
  }
  // "no, dark green", "actually red please": a colour said alone recolours what was spoken of last.
  if (const auto colour = bare_color(c)) return revises_last("make it " + *colour);
  // "2 m forward", "another 10 degrees left": an amount and a direction with nothing else named
  // moves the view.
  if (has_amount && has_any(c, {"forward", "ahead", "back", "backward", "left", "right", "up", "down", "higher", "lower"})) {
    in.kind = "view";
    return in;
  }
  in.kind = "unclear";
  return in;
}

}  // namespace chatsim::agents::manager::detail
