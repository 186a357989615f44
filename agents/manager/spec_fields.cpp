// Commands written as a test spec ("Actor: grey Volvo XC90. Start: 25 m ahead in ego lane.
// Speed: 20 km/h", "Spawn NPC: type=taxi, colour=yellow, ...") become one plain sentence, so the
// fields of one actor stay one instruction instead of a clause each.
#include "agents/manager/spec_fields.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"

namespace chatsim::agents::manager {
namespace {

enum class Role { title, verb, actor, colour, position, speed, heading, action, count };

// The keys a spec uses, by what their value says.
const std::map<std::string, Role>& keys() {
  static const std::map<std::string, Role> k{
      {"scenario", Role::title}, {"test", Role::title}, {"case", Role::title}, {"title", Role::title},
      {"name", Role::title}, {"actor", Role::actor}, {"vehicle", Role::actor}, {"npc", Role::actor},
      {"object", Role::actor}, {"agent", Role::actor}, {"target", Role::actor}, {"type", Role::actor},
      {"class", Role::actor}, {"model", Role::actor}, {"make", Role::actor}, {"brand", Role::actor},
      {"colour", Role::colour}, {"color", Role::colour}, {"paint", Role::colour}, {"position", Role::position},
      {"start", Role::position}, {"start position", Role::position}, {"initial position", Role::position},
      {"location", Role::position}, {"pos", Role::position}, {"place", Role::position}, {"spawn", Role::position},
      {"distance", Role::position}, {"lane", Role::position}, {"where", Role::position}, {"speed", Role::speed},
      {"velocity", Role::speed}, {"initial speed", Role::speed}, {"heading", Role::heading},
      {"direction", Role::heading}, {"orientation", Role::heading}, {"action", Role::action},
      {"behaviour", Role::action}, {"behavior", Role::action}, {"manoeuvre", Role::action},
      {"maneuver", Role::action}, {"motion", Role::action}, {"count", Role::count}, {"number", Role::count},
      {"quantity", Role::count}};
  return k;
}

std::string trimmed_lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const size_t a = s.find_first_not_of(" \t\r\n\"'");
  const size_t b = s.find_last_not_of(" \t\r\n\"'");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// Segments between separators: ". " (not a decimal point), ";", ",", newlines.
std::vector<std::string> segments(const std::string& s) {
  std::vector<std::string> out(1);
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const bool stop = c == '.' && (i + 1 == s.size() || std::isspace(static_cast<unsigned char>(s[i + 1])));
    if (stop || c == ';' || c == ',' || c == '\n') {
      out.emplace_back();
      continue;
    }
    out.back().push_back(c);
  }
  return out;
}

// "ego lane" is my lane, "same as ego" the same way as me: the words the rest of the manager reads.
// Word by word, so that no word merely containing "ego" changes.
std::string in_plain_words(const std::string& v) {
  std::istringstream in(v);
  std::vector<std::string> w;
  for (std::string word; in >> word;) w.push_back(word);
  std::string out;
  for (size_t i = 0; i < w.size(); ++i) {
    std::string word = w[i];
    if (word == "ego" || word == "ego's") {
      if (i + 1 < w.size() && w[i + 1] == "vehicle") ++i;  // "the ego vehicle": me
      word = i + 1 < w.size() && w[i + 1] == "lane" ? "my" : "me";
      if (out == "the") out.clear();  // "the ego": me
      else if (out.ends_with(" the")) out.resize(out.size() - 4);
    }
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}

std::string heading_phrase(const std::string& v) {
  const auto w = text::words(v);
  if (text::has_any(w, {"same", "along", "with"})) return "going the same way as me";
  if (text::has_any(w, {"opposite", "toward", "towards", "oncoming", "against", "facing"})) return "coming toward me";
  if (text::has_any(w, {"away"})) return "driving away from me";
  return v;
}

struct Spec {
  std::map<Role, std::vector<std::string>> values;
  std::string verb;
  int known = 0;
};

void read_field(const std::string& segment, Spec& spec) {
  const size_t sep = segment.find_first_of(":=");
  if (sep == std::string::npos) {
    if (const std::string v = trimmed_lower(segment); !v.empty()) spec.values[Role::position].push_back(v);
    return;
  }
  const std::string key = trimmed_lower(segment.substr(0, sep)), value = segment.substr(sep + 1);
  if (const auto k = keys().find(key); k != keys().end()) {
    ++spec.known;
    if (value.find_first_of(":=") != std::string::npos) return read_field(value, spec);
    if (const std::string v = trimmed_lower(value); !v.empty()) spec.values[k->second].push_back(v);
    return;
  }
  // "Spawn NPC: type=taxi": a heading that is an order; its first word is the verb.
  const auto w = text::words(key);
  if (!w.empty() && spec.verb.empty()) spec.verb = w.front();
  read_field(value, spec);
}

std::string joined(const Spec& spec, Role role) {
  const auto it = spec.values.find(role);
  if (it == spec.values.end()) return "";
  std::string out;
  for (const auto& v : it->second) out += (out.empty() ? "" : " ") + in_plain_words(v);
  return out;
}

}  // namespace

std::optional<std::string> spec_as_sentence(const std::string& command) {
  if (command.find_first_of(":=") == std::string::npos) return std::nullopt;
  Spec spec;
  for (const auto& s : segments(command)) read_field(s, spec);
  if (spec.known < 2) return std::nullopt;  // a colon in a sentence ("Simulate a breakdown: ...")
  const std::string action = joined(spec, Role::action), actor = joined(spec, Role::actor);
  const auto action_words = text::words(action);
  const bool removal = text::has_any(action_words, {"delete", "remove", "erase", "despawn", "destroy"});
  std::string out = removal ? "remove" : "add";
  const auto say = [&out](const std::string& part) {
    if (!part.empty()) out += " " + part;
  };
  if (!removal) {
    const std::string count = joined(spec, Role::count);
    say(count.empty() ? "a" : count);
    say(joined(spec, Role::colour));
  }
  say(actor.empty() ? "vehicle" : actor);
  const std::string title = joined(spec, Role::title), heading = joined(spec, Role::heading);
  std::string position = joined(spec, Role::position);
  if (position.starts_with("my lane") || position.starts_with("lane")) position = "in " + position;
  const std::string speed = joined(spec, Role::speed);
  for (const std::string& part : {position, heading.empty() ? std::string() : heading_phrase(heading),
                                  speed.empty() ? std::string() : "at " + speed, removal ? std::string() : action})
    say(part);
  // "Scenario: lead vehicle": ahead of the ego, going its way, unless the fields say otherwise.
  if (heading.empty() && text::has_any(text::words(title), {"lead", "leading", "car following", "follow"}))
    say("going the same way as me");
  return out;
}

// "Simulate a breakdown: a van stopped in my lane, cones behind it": a title the detail after the
// colon carries out; it stays only when it is something to do by itself.
std::vector<Instruction> titled(const std::string& sentence, size_t colon) {
  auto title = decompose(sentence.substr(0, colon));
  // "clear the works area: the digger, the dumper and the trailer": a removal whose detail only
  // names what goes.
  const auto head = text::words(sentence.substr(0, colon));
  const auto named = text::words(sentence.substr(colon + 1));
  const bool removal = title.size() == 1 && (title[0].kind == "delete" ||
                                             (!head.empty() && text::has_any({head[0]}, {"clear", "empty", "remove"})));
  if (removal && !named.empty() && text::has_any({named[0]}, {"the", "both", "those", "these", "all", "every", "any"}))
    return decompose("remove " + sentence.substr(colon + 1));
  // "del: motorbike", "add: red suv": a title that is a verb alone acts on the detail.
  if (head.size() == 1 && text::has_any(head, {"add", "insert", "put", "place", "remove", "delete", "erase", "clear"}) &&
      !named.empty())
    return decompose(head[0] + " " + sentence.substr(colon + 1));
  auto body = decompose(sentence.substr(colon + 1));
  // "Make it look like school's out: ..." describes the scene the detail builds.
  const bool scene_title = text::has_any(head, {"look like", "looks like", "as if", "as though", "feel like"});
  const auto unclear = [](const Instruction& i) { return i.kind == "unclear"; };
  // "Busy morning: a few more cars parked on the left": a scene named by a mood, which the detail
  // makes (not a second scene on top of it).
  const bool mood_title = std::all_of(title.begin(), title.end(), [](const Instruction& i) {
    return i.kind == "busy_road" && !detail::mentions_vehicle(text::words(i.text));
  });
  if ((scene_title || mood_title || std::all_of(title.begin(), title.end(), unclear)) &&
      !std::all_of(body.begin(), body.end(), unclear))
    title.clear();
  title.insert(title.end(), body.begin(), body.end());
  return title;
}

}  // namespace chatsim::agents::manager
