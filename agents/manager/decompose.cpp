// The manager's offline decomposition: a command split into sentences, clauses and single
// instructions (what each clause is: classify.cpp).
#include "agents/manager/decompose.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <optional>
#include <regex>

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"
#include "agents/manager/spec_fields.hpp"

namespace chatsim::agents::manager {
namespace {

using Words = std::vector<std::string>;
using detail::add_verbs;
using detail::classify;
using detail::delete_verbs;
using detail::mentions_vehicle;

// "..., cones behind it" after an addition: a bare plural noun (no article) after a comma adds
// those things too.
bool bare_plural_addition(const Words& w, size_t i, const Words& clause_so_far) {
  if (clause_so_far.empty()) return false;
  const auto types = lexicon::find_types(Words(w.begin() + long(i), w.begin() + long(std::min(w.size(), i + 3))));
  if (types.empty() || types.front().begin != 0 || !types.front().plural || types.front().type.living())
    return false;
  return classify(clause_so_far).kind == "add";
}

bool starts_instruction(const std::string& w) {
  for (const auto* list : {&add_verbs(), &delete_verbs()})
    if (std::find(list->begin(), list->end(), w) != list->end()) return true;
  static const char* v[] = {"move", "shift", "raise", "lower", "rotate", "turn", "look", "pan", "tilt", "make",
                            "change", "modify", "set", "paint", "repaint", "respray", "recolor", "restore", "undo", "simulate",
                            "ego", "swap", "replace", "lift", "nudge", "step", "swing", "yaw", "send"};
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
    // "turn left / remove the van": a slash or bar standing apart from its words parts a list
    // ("km/h" and "w/o" keep theirs).
    const bool apart = (c == '/' || c == '|') && ((i > 0 && std::isspace(static_cast<unsigned char>(s[i - 1]))) ||
                                                  (i + 1 < s.size() && std::isspace(static_cast<unsigned char>(s[i + 1]))));
    if ((c == '.' && !decimal) || c == '!' || c == '?' || c == ';' || c == '\n' || apart) {
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

// "make it an estate, a volvo v70": after "make it / turn it into ...", a vehicle named after a
// comma with no verb to its end says the same thing again.
bool apposition(const Words& clause_so_far, const Words& w, size_t i) {
  if (clause_so_far.size() < 3 || (clause_so_far[1] != "it" && clause_so_far[1] != "them")) return false;
  const std::string& verb = clause_so_far[0];
  if (verb != "make" && verb != "turn" && verb != "change" && verb != "swap" && verb != "switch") return false;
  return std::none_of(w.begin() + long(i), w.end(), [](const std::string& x) { return starts_instruction(x); });
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
      // "... and have a black cab drive ahead of us": a new vehicle made to do something.
      const bool have_object =
          j + 1 < w.size() && (w[j] == "have" || w[j] == "let") &&
          (w[j + 1] == "the" || w[j + 1] == "it" || w[j + 1] == "them" || w[j + 1] == "ego" ||
           ((w[j + 1] == "a" || w[j + 1] == "an" || text::is_number_word(w[j + 1])) &&
            mentions_vehicle(Words(w.begin() + long(j + 1), w.begin() + long(std::min(w.size(), j + 6))))));
      // "... and drive the camera 10 m forward", "and bring the view down": any verb on the camera.
      const bool camera_object = j + 2 < w.size() && (w[j + 1] == "the" || w[j + 1] == "my" || w[j + 1] == "our") &&
                                 (w[j + 2] == "camera" || w[j + 2] == "view" || w[j + 2] == "viewpoint");
      if (j < w.size() &&
          (starts_instruction(w[j]) || have_object || camera_object || (comma_before[i] && names_new_part(w, j)))) {
        split = true;
        i = j - 1;  // drop the connector words
      }
    } else if (comma_before[i] && (starts_instruction(w[i]) || (names_new_part(w, i) && !apposition(out.back(), w, i)))) {
      out.emplace_back();
    } else if (comma_before[i] && bare_plural_addition(w, i, out.back())) {
      out.emplace_back(Words{"add"});
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
                                 "could we have", "can we have", "could we get", "can we get", "could i have",
                                 "can i have", "can i get", "could i get", "we need", "we want", "give me", "show me",
                                 "id like you to", "i'd like you to", "kindly", "lets", "let us", "go ahead and", "try to",
                                 "no wait", "no sorry", "no actually", "wait no", "hang on", "hold on", "scratch that",
                                 "on second thought", "on second thoughts", "second thoughts"};
  // Fillers and politeness in any order ("hey, can you ...", "ok so please ..."), until none is left.
  static const char* fillers[] = {"additionally", "also", "then", "now", "please", "and", "finally", "next", "first",
                                  "lastly", "ok", "okay", "actually", "sorry", "wait", "oh", "hmm", "hey", "hi",
                                  "hello", "so", "um", "uh", "well", "alright", "maybe", "perhaps", "possibly"};
  // "I want the car park to look busy, so could you fill the bays with parked cars": what is asked
  // follows "so"; what comes before it is why.
  for (auto& c : out)
    for (const char* ask : {"so could you", "so can you", "so would you", "so will you", "so please"})
      if (const size_t at = text::find_phrase(c, ask); at != std::string::npos && at > 0) {
        c.erase(c.begin(), c.begin() + long(at) + 1);
        break;
      }
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
      const bool filler = !c.empty() && std::any_of(std::begin(fillers), std::end(fillers),
                                                    [&](const char* f) { return c.front() == f; });
      // "please to remove the car": an infinitive's "to" before the verb says nothing.
      const bool infinitive = c.size() > 1 && c.front() == "to" && starts_instruction(c[1]);
      if (filler || infinitive || (!c.empty() && c.front() == "no" && !mentions_vehicle(c))) {
        c.erase(c.begin());
        again = true;
      }
    }
  out.erase(std::remove_if(out.begin(), out.end(), [](const Words& c) { return c.empty(); }), out.end());
  return out;
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
          !types.front().type.living() && types.front().type.type != "object") {
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
       w[0] == "color" || w[0] == "set" || w[0] == "put" || w[0] == "place" || w[0] == "position" || w[0] == "get" ||
       w[0] == "bring" || w[0] == "send" || w[0] == "drop" || w[0] == "shift" || w[0] == "slow" || w[0] == "speed"))
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

namespace {
// A sentence's words, and which ones had a comma (or colon) before them; turns become degrees
// per comma part so that the flags stay on their words.
void words_with_commas(const std::string& sentence, Words& w, std::vector<bool>& comma) {
  bool pending_comma = false;
  std::string cur;
  for (size_t i = 0; i <= sentence.size(); ++i) {
    const char ch = i < sentence.size() ? sentence[i] : ',';
    if (ch != ',' && ch != ':') {
      cur.push_back(ch);
      continue;
    }
    auto ws = text::words(cur);
    text::turns_to_degrees(ws);
    text::bare_turns_to_degrees(ws);
    for (size_t k = 0; k < ws.size(); ++k) {
      w.push_back(ws[k]);
      comma.push_back(k == 0 && pending_comma);
    }
    cur.clear();
    pending_comma = true;
  }
}

}  // namespace

namespace {

// "add a green tram... sorry, a green bus", "a red car, no wait, a blue one": a self-correction
// replaces the noun phrase before it with the one after it.
std::string without_self_corrections(std::string command) {
  static const char* kMarkers[] = {"no wait", "wait no", "no sorry", "sorry", "i mean", "or rather", "no, wait", "wait, no"};
  const auto starts_phrase = [](const std::string& t, size_t at) {
    for (const char* a : {"a ", "an ", "the ", "one ", "two ", "three "})
      if (t.compare(at, std::strlen(a), a) == 0) return true;
    return at < t.size() && std::isdigit(static_cast<unsigned char>(t[at]));
  };
  for (bool again = true; again;) {
    again = false;
    std::string lower = command;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    for (const char* marker : kMarkers) {
      const size_t at = lower.find(marker);
      if (at == std::string::npos || at == 0) continue;
      size_t next = at + std::strlen(marker);
      while (next < lower.size() && (lower[next] == ' ' || lower[next] == ',' || lower[next] == '.')) ++next;
      if (!starts_phrase(lower, next)) continue;
      // The phrase corrected: from the last article within 60 characters before the marker.
      const size_t from = at > 60 ? at - 60 : 0;
      size_t cut = std::string::npos;
      for (const char* a : {" a ", " an ", " the "})
        if (const size_t p = lower.rfind(a, at); p != std::string::npos && p >= from && (cut == std::string::npos || p > cut))
          cut = p + 1;
      if (cut == std::string::npos) continue;
      command.erase(cut, next - cut);
      again = true;
      break;
    }
  }
  return command;
}

// "1) remove the bus 2) add a car", "(a) ... (b) ...", "- remove the bus" on lines of their own:
// list markers end a sentence; a number only when a bracket follows it or it opens a line.
std::string without_list_markers(const std::string& command) {
  static const std::regex kBracketed(R"((^|\s)\(?(\d{1,2}|[a-hA-H])\)\s+)");
  static const std::regex kLineStart(R"((^|[\n;])\s*(\d{1,2}[.:]|[-*]|•)\s+)");
  return std::regex_replace(std::regex_replace(command, kBracketed, ". "), kLineStart, "$1. ");
}

// "Don't touch the trucks, but get rid of every car on the left": what is not to be touched is
// an exception to what follows "but" ("get rid of every car on the left except the trucks").
std::string negation_as_exception(const std::string& sentence) {
  static const std::regex kNegated(
      R"(^\s*(?:please\s+)?(?:don'?t|do not|never)\s+)"
      R"((?:touch|remove|delete|erase|move|change|get rid of|take out|take away)\s+)"
      R"((.+?)\s*,?\s+but\s+(?:please\s+)?(.+)$)",
      std::regex::icase);
  std::smatch m;
  if (!std::regex_match(sentence, m, kNegated)) return sentence;
  return m[2].str() + " except " + m[1].str();
}

// "w/ its lights on, put a police car behind the bus": a leading "with ..." phrase says how the
// next clause's vehicle is; it goes to the end of that clause.
std::vector<Words> with_phrases_attached(const std::vector<Words>& parts) {
  std::vector<Words> out;
  Words pending;  // "with ..." phrases waiting for the clause they describe
  for (const auto& p : parts) {
    const bool with_phrase = !p.empty() && (p.front() == "with" || p.front() == "without") &&
                             std::none_of(p.begin(), p.end(), [](const std::string& x) { return starts_instruction(x); });
    if (with_phrase && &p != &parts.back()) {
      pending.insert(pending.end(), p.begin(), p.end());
      continue;
    }
    out.push_back(p);
    out.back().insert(out.back().end(), pending.begin(), pending.end());
    pending.clear();
  }
  return out;
}

// "the white van has broken down and a tow truck is parked behind it": a clause saying how a
// vehicle already there is ("the ... has / is ...") asks for nothing when a later clause calls it
// "it"; that "it" is the vehicle. Returns the noun phrase.
std::optional<Words> described_vehicle(const Words& c) {
  if (c.size() < 3 || c.front() != "the") return std::nullopt;
  const auto types = lexicon::find_types(c);
  if (types.empty() || types.front().type.living()) return std::nullopt;
  const size_t end = types.front().end;
  static const char* kStates[] = {"has", "is", "was", "had", "gets", "got", "just"};
  const auto is_state = [&](const char* x) { return c[end] == x; };
  if (end >= c.size() || std::none_of(std::begin(kStates), std::end(kStates), is_state)) return std::nullopt;
  return Words(c.begin(), c.begin() + long(end));
}

// The sentence without such a clause (up to its "and"), "it" after it replaced by the vehicle.
void resolve_description(Words& w, std::vector<bool>& comma) {
  const auto described = described_vehicle(w);
  if (!described) return;
  const auto and_at = std::find(w.begin() + long(described->size()), w.end(), "and");
  const auto it_at = std::find(and_at, w.end(), "it");
  if (and_at == w.end() || it_at == w.end()) return;
  const long it = it_at - w.begin(), cut = and_at - w.begin() + 1;
  w.erase(w.begin() + it);
  w.insert(w.begin() + it, described->begin(), described->end());
  comma.erase(comma.begin() + it);
  comma.insert(comma.begin() + it, described->size(), false);
  w.erase(w.begin(), w.begin() + cut);
  comma.erase(comma.begin(), comma.begin() + cut);
}

}  // namespace

std::vector<Instruction> decompose(const std::string& command_in) {
  std::vector<Instruction> out;
  const std::string listed = without_list_markers(command_in);
  const std::string command = without_self_corrections(spec_as_sentence(listed).value_or(listed));
  for (const auto& said : sentences(command)) {
    const std::string sentence = negation_as_exception(said);
    if (const size_t colon = sentence.find(':'); colon != std::string::npos) {
      const auto parts = titled(sentence, colon);
      out.insert(out.end(), parts.begin(), parts.end());
      continue;
    }
    Words w;
    std::vector<bool> comma;
    words_with_commas(sentence, w, comma);
    lexicon::correct_typos(w, text::capitalised_words(sentence));
    std::string previous;
    resolve_description(w, comma);
    for (const auto& c : with_phrases_attached(clauses(w, comma))) {
      Instruction in = classify(c);
      // "raise the camera 2 m and move it 1 m left", "... and drop it 0.3 m": "it" is the camera
      // of the clause before.
      if ((in.kind == "revise" || in.kind == "unclear") && previous == "view" && !mentions_vehicle(c) &&
          detail::says_amount(c)) {
        in.kind = "view";
        in.target.clear();
      }
      // "have a tahoe come from the right and turn left in front of us": a motion with no subject
      // after an addition is how that vehicle moves.
      static const char* kMotionVerbs[] = {"turn", "turns", "drive", "drives", "go", "goes", "park", "parks", "stop",
                                           "stops", "pull", "pulls", "overtake", "overtakes", "reverse", "reverses",
                                           "head", "heads", "merge", "merges", "speed", "slow", "come", "comes"};
      const bool bare_motion = std::any_of(std::begin(kMotionVerbs), std::end(kMotionVerbs),
                                           [&](const char* v) { return c.front() == v; }) &&
                               !mentions_vehicle(c) && !text::has_any(c, {"it", "them", "camera", "view", "ego"});
      if (bare_motion && previous == "add" && !out.empty() && out.back().kind == "add" &&
          (in.kind == "unclear" || in.kind == "view") &&
          !detail::says_amount(c)) {
        out.back().text += " and " + in.text;
        continue;
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
