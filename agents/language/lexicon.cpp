#include "agents/language/lexicon.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "agents/language/makes.hpp"
#include "agents/language/text.hpp"

namespace chatsim::agents::lexicon {
namespace {

using detail::is_unit_word;
using detail::makes;
using detail::vocabulary_file;
using detail::words_at;

struct NamedColor {
  const char* name;
  Rgb rgb;
};

// Base colours; "dark"/"light" variants are derived.
const std::vector<NamedColor>& base_colors() {
  static const std::vector<NamedColor> c{
      {"red", {200, 25, 25}},       {"orange", {240, 120, 20}},   {"yellow", {240, 205, 25}},
      {"green", {30, 140, 50}},     {"blue", {30, 60, 200}},      {"purple", {120, 40, 165}},
      {"violet", {130, 60, 190}},   {"pink", {230, 100, 170}},    {"magenta", {200, 30, 160}},
      {"white", {240, 240, 240}},   {"black", {20, 20, 22}},      {"gray", {128, 128, 132}},
      {"silver", {175, 177, 182}},  {"brown", {110, 65, 30}},     {"beige", {215, 200, 160}},
      {"gold", {210, 170, 40}},     {"golden", {210, 170, 40}},   {"maroon", {120, 20, 30}},
      {"navy", {20, 30, 110}},      {"teal", {20, 128, 128}},     {"cyan", {30, 190, 220}},
      {"turquoise", {40, 200, 190}}, {"lime", {120, 210, 40}},    {"crimson", {180, 20, 40}},
      {"scarlet", {220, 35, 20}},   {"olive", {110, 110, 30}},    {"cream", {240, 230, 200}},
      {"ivory", {240, 238, 225}},   {"charcoal", {55, 57, 60}},   {"champagne", {220, 205, 170}},
      {"bronze", {160, 110, 50}},   {"tan", {200, 170, 120}},     {"burgundy", {110, 20, 40}},
      {"indigo", {60, 30, 140}},    {"lavender", {170, 140, 210}}, {"khaki", {190, 180, 120}}};
  return c;
}

Rgb shade(const Rgb& c, double f) {
  Rgb out{};
  for (int i = 0; i < 3; ++i) out[size_t(i)] = std::clamp(int(std::lround(c[size_t(i)] * f)), 0, 255);
  return out;
}

Rgb tint(const Rgb& c, double f) {
  Rgb out{};
  for (int i = 0; i < 3; ++i) out[size_t(i)] = std::clamp(int(std::lround(c[size_t(i)] + (255 - c[size_t(i)]) * f)), 0, 255);
  return out;
}

const std::map<std::string, VehicleType>& types() {
  static const std::map<std::string, VehicleType> t{
      {"car", {"car", "vehicle.car", "vehicle"}},
      {"suv", {"suv", "vehicle.car", "vehicle"}},
      {"truck", {"truck", "vehicle.truck", "vehicle.truck"}},
      {"bus", {"bus", "vehicle.bus.rigid", "vehicle.bus"}},
      {"van", {"van", "vehicle.car", "vehicle"}},
      {"police", {"police", "vehicle.emergency.police", "vehicle.emergency.police"}},
      {"taxi", {"taxi", "vehicle.car", "vehicle"}},
      {"ambulance", {"ambulance", "vehicle.emergency.ambulance", "vehicle.emergency.ambulance"}},
      {"firetruck", {"firetruck", "vehicle.emergency.firetruck", "vehicle.emergency"}},
      {"motorcycle", {"motorcycle", "vehicle.motorcycle", "vehicle.motorcycle"}},
      {"bicycle", {"bicycle", "vehicle.bicycle", "vehicle.bicycle"}},
      // nuScenes' construction vehicles and trailers: no asset of their own (a truck stands in).
      {"construction", {"construction", "vehicle.construction", "vehicle.construction"}},
      {"trailer", {"trailer", "vehicle.trailer", "vehicle.trailer"}},
      // Labelled in some datasets (KITTI's Tram, nuScenes' animal): selectable, never added.
      {"tram", {"tram", "vehicle.tram", "vehicle.tram"}},
      {"animal", {"animal", "animal", "animal"}},
      {"cone", {"cone", "movable_object.trafficcone", "movable_object.trafficcone"}},
      {"barrier", {"barrier", "movable_object.barrier", "movable_object.barrier"}},
      {"pedestrian", {"pedestrian", "human.pedestrian.adult", "human"}},
      {"object", {"object", "", ""}}};
  return t;
}

struct Noun {
  std::string phrase;
  std::string type;
  bool plural;
  std::vector<std::string> words;  // the phrase split once, at load: find_types runs per clause
};

// The nouns of agents/prompts/nouns.json, longest phrases first so that "police car" wins over
// "car" and "people carrier" over "people".
const std::vector<Noun>& nouns() {
  static const std::vector<Noun> n = [] {
    const auto file = vocabulary_file().parent_path() / "nouns.json";
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot read the noun list " + file.string() +
                               " (set CHATSIM_PROMPTS to the agents/prompts folder)");
    std::vector<Noun> list;
    try {
      const auto doc = nlohmann::json::parse(in);
      for (const auto& e : doc.at("nouns")) {
        Noun noun{e.at("phrase").get<std::string>(), e.at("type").get<std::string>(), e.value("plural", false), {}};
        noun.words = text::words(noun.phrase);
        if (types().count(noun.type) == 0) {
          std::string known;
          for (const auto& [name, type] : types()) known += (known.empty() ? "" : ", ") + name;
          throw std::runtime_error(file.string() + ": the noun '" + noun.phrase + "' has the unknown type '" + noun.type +
                                   "' (nouns[].type: one of " + known + ")");
        }
        list.push_back(std::move(noun));
      }
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(file.string() + ": not a noun list (nouns: [{phrase, type, plural}]): " + e.what());
    }
    std::stable_sort(list.begin(), list.end(), [](const Noun& a, const Noun& b) {
      return a.words.size() > b.words.size();
    });
    return list;
  }();
  return n;
}

// At most one edit apart: an insertion, a deletion, a substitution, or a swap of neighbours.
bool one_edit_apart(const std::string& a, const std::string& b) {
  if (a == b) return false;
  const size_t n = a.size(), m = b.size();
  if (n == m) {
    size_t first = n;
    for (size_t i = 0; i < n; ++i)
      if (a[i] != b[i]) {
        first = i;
        break;
      }
    size_t diffs = 0;
    for (size_t i = 0; i < n; ++i) diffs += a[i] != b[i];
    if (diffs == 1) return true;
    return diffs == 2 && first + 1 < n && a[first] == b[first + 1] && a[first + 1] == b[first] &&
           a.substr(first + 2) == b.substr(first + 2);
  }
  if (n + 1 != m && m + 1 != n) return false;
  const std::string& shorter = n < m ? a : b;
  const std::string& longer = n < m ? b : a;
  size_t i = 0;
  while (i < shorter.size() && shorter[i] == longer[i]) ++i;
  return shorter.substr(i) == longer.substr(i + 1);
}

bool is_swap(const std::string& a, const std::string& b) {
  return a.size() == b.size() && a != b && one_edit_apart(a, b) &&
         std::count_if(a.begin(), a.end(), [&, i = size_t(0)](char c) mutable { return c != b[i++]; }) == 2;
}

const std::vector<std::string>& known_words() {
  static const std::vector<std::string> known = [] {
    std::vector<std::string> out;
    const auto file = vocabulary_file().parent_path() / "words.json";
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("cannot read the word list " + file.string() +
                               " (set CHATSIM_PROMPTS to the agents/prompts folder)");
    try {
      const auto doc = nlohmann::json::parse(in);  // named: a temporary would die before the loop runs
      for (const auto& w : doc.at("words")) out.push_back(w.get<std::string>());
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(file.string() + ": not a word list (words: [...]): " + e.what());
    }
    for (const auto& c : base_colors()) out.push_back(c.name);
    for (const auto& n : nouns())
      out.insert(out.end(), n.words.begin(), n.words.end());
    for (const auto& m : makes()) {
      for (const auto& name : m.names) out.insert(out.end(), name.begin(), name.end());
      for (const auto& model : m.models) out.insert(out.end(), model.first.begin(), model.first.end());
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }();
  return known;
}

// English words (Debian's wamerican and wbritish lists, lower case): never taken for typos.
const std::unordered_set<std::string>& english_words() {
  static const std::unordered_set<std::string> words = [] {
    std::unordered_set<std::string> out;
    std::vector<std::filesystem::path> files{"/usr/share/dict/american-english", "/usr/share/dict/british-english"};
    if (const char* env = std::getenv("CHATSIM_WORDLIST"); env != nullptr && *env != '\0') files = {env};
    for (const auto& f : files) {
      std::ifstream in(f);
      for (std::string line; std::getline(in, line);) {
        if (line.size() > 2 && line.compare(line.size() - 2, 2, "'s") == 0) continue;
        std::transform(line.begin(), line.end(), line.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        out.insert(line);
      }
    }
    return out;
  }();
  return words;
}

}  // namespace

void load_vocabulary() {
  (void)known_words();  // makes, nouns and words.json
  (void)english_words();
}

bool is_domain_word(const std::string& w) {
  const auto& known = known_words();
  return std::binary_search(known.begin(), known.end(), w);
}

bool is_english_word(const std::string& w) { return english_words().contains(w); }

std::optional<std::pair<size_t, size_t>> unknown_vehicle_name(const std::vector<std::string>& w, size_t from) {
  if (english_words().empty()) return std::nullopt;
  size_t i = from;
  while (i < w.size() && (detail::is_vehicle_determiner(w[i]) || detail::is_vehicle_premodifier(w[i]) ||
                          is_color_word(w[i]) || text::is_number_word(w[i])))
    ++i;
  const auto unknown = [&](const std::string& x) {
    const bool digits = std::any_of(x.begin(), x.end(), [](char c) { return c >= '0' && c <= '9'; });
    return !is_domain_word(x) && !is_unit_word(x) && (digits ? !text::is_number_word(x) : !english_words().contains(x));
  };
  size_t end = i;
  while (end < w.size() && end - i < 3 && unknown(w[end])) ++end;
  if (end == i || std::isdigit(static_cast<unsigned char>(w[i][0]))) return std::nullopt;  // a name starts with a letter
  return std::make_pair(i, end);
}

namespace {

std::optional<std::string> undoubled_vehicle_noun(const std::string& word) {
  for (size_t i = 1; i < word.size(); ++i) {
    if (word[i] != word[i - 1]) continue;
    const std::string shorter = word.substr(0, i) + word.substr(i + 1);
    if (!find_types({shorter}).empty()) return shorter;
  }
  return std::nullopt;
}

}  // namespace

void correct_typos(std::vector<std::string>& w, const std::set<std::string>& names) {
  const auto& english = english_words();
  if (english.empty()) return;  // without a word list every unknown word could be a name: change nothing
  const auto& known = known_words();
  for (auto& word : w) {
    if (std::binary_search(known.begin(), known.end(), word) || names.contains(word)) continue;
    // A vehicle noun typed with a doubled letter can be a rare English word ("buss"): in a
    // command about vehicles it is the noun.
    if (english.contains(word)) {
      if (const auto noun = undoubled_vehicle_noun(word)) word = *noun;
      continue;
    }
    if (word.size() < 3 || text::is_number_word(word)) continue;
    if (!std::all_of(word.begin(), word.end(), [](char c) { return c >= 'a' && c <= 'z'; })) continue;
    const std::string* match = nullptr;
    int found = 0;
    for (const auto& k : known) {
      if (k.size() < 3 || (word.size() == 3 ? !is_swap(word, k) : (k.size() < 4 || !one_edit_apart(word, k)))) continue;
      match = &k;
      ++found;
    }
    if (found == 1) word = *match;
  }
}

std::string color_class(const Rgb& rgb) {
  const double r = rgb[0] / 255.0, g = rgb[1] / 255.0, b = rgb[2] / 255.0;
  const double mx = std::max({r, g, b}), mn = std::min({r, g, b});
  const double l = (mx + mn) / 2, d = mx - mn;
  const double s = d == 0 ? 0 : d / (1 - std::abs(2 * l - 1));
  if (l < 0.16) return "black";
  if (s < 0.2 || d < 0.08) return l > 0.8 ? "white" : (l < 0.2 ? "black" : "gray");
  if (l > 0.92) return "white";
  double h = 0;
  if (mx == r) h = 60 * std::fmod((g - b) / d + 6, 6);
  else if (mx == g) h = 60 * ((b - r) / d + 2);
  else h = 60 * ((r - g) / d + 4);
  if (h < 15 || h >= 340) return "red";
  if (h < 42) return "orange";
  if (h < 70) return "yellow";
  if (h < 165) return "green";
  if (h < 255) return "blue";
  return "purple";
}

bool is_color_word(const std::string& w) {
  for (const auto& c : base_colors())
    if (w == c.name) return true;
  return false;
}

std::vector<ColorMention> find_colors(const std::vector<std::string>& w) {
  std::vector<ColorMention> out;
  for (size_t i = 0; i < w.size(); ++i) {
    for (const auto& c : base_colors()) {
      if (w[i] != c.name) continue;
      ColorMention m{c.name, c.rgb, i, i + 1};
      if (i > 0 && (w[i - 1] == "dark" || w[i - 1] == "deep")) {
        m = {w[i - 1] + " " + c.name, shade(c.rgb, 0.55), i - 1, i + 1};
      } else if (i > 0 && (w[i - 1] == "light" || w[i - 1] == "pale" || w[i - 1] == "bright")) {
        m = {w[i - 1] + " " + c.name, w[i - 1] == "bright" ? c.rgb : tint(c.rgb, 0.45), i - 1, i + 1};
      } else if (i > 0 && (w[i - 1] == "metallic")) {
        m.begin = i - 1;
      }
      out.push_back(m);
    }
  }
  return out;
}

const VehicleType* vehicle_type(const std::string& type) {
  const auto it = types().find(type);
  return it == types().end() ? nullptr : &it->second;
}

std::vector<TypeMention> find_types(const std::vector<std::string>& w) {
  std::vector<TypeMention> out;
  std::vector<bool> used(w.size(), false);
  for (const auto& n : nouns()) {
    const auto& nw = n.words;
    for (size_t at = 0; at + nw.size() <= w.size(); ++at) {
      if (!words_at(w, at, nw)) continue;
      bool free = true;
      for (size_t k = 0; k < nw.size(); ++k) free = free && !used[at + k];
      if (!free) continue;
      // "the bus bay", "a bus stop", "the car park", "a taxi rank": a place named after a vehicle.
      // "two car lengths", "a bus length": a unit of length (text::length_units), not a vehicle.
      static const char* kPlaces[] = {"bay", "bays", "stop", "stops", "lane", "lanes", "station", "shelter", "park",
                                      "rank", "depot", "garage", "wash", "dealership", "length", "lengths"};
      // "the traffic lights", "a traffic island": a thing named after traffic.
      static const char* kTrafficThings[] = {"light", "lights", "signal", "signals", "sign", "signs", "island",
                                             "islands", "calming", "warden", "wardens"};
      const size_t after = at + nw.size();
      // "a motorbike lane splitting": riding between lanes, not a lane.
      const bool activity = after + 1 < w.size() && (w[after + 1] == "splitting" || w[after + 1] == "filtering");
      if (after < w.size() && !activity &&
          std::any_of(std::begin(kPlaces), std::end(kPlaces), [&](const char* p) { return w[after] == p; }))
        continue;
      if (after < w.size() && nw.size() == 1 && nw[0] == "traffic" &&
          std::any_of(std::begin(kTrafficThings), std::end(kTrafficThings), [&](const char* p) { return w[after] == p; }))
        continue;
      for (size_t k = 0; k < nw.size(); ++k) used[at + k] = true;
      out.push_back({types().at(n.type), at, at + nw.size(), n.plural});
    }
  }
  std::sort(out.begin(), out.end(), [](const TypeMention& a, const TypeMention& b) { return a.begin < b.begin; });
  // "a guy on a motorbike", "a woman driving a taxi": the vehicle, not its rider.
  for (size_t i = 0; i + 1 < out.size(); ++i) {
    if (!out[i].type.living() || out[i + 1].type.living() || out[i + 1].begin > out[i].end + 3) continue;
    const std::vector<std::string> between(w.begin() + long(out[i].end), w.begin() + long(out[i + 1].begin));
    if (text::has_any(between, {"on", "riding", "driving", "in", "astride", "with"})) out.erase(out.begin() + long(i--));
  }
  return out;
}

const std::vector<std::string>& place_of_removed_phrases() {
  static const std::vector<std::string> kPhrases{
      "in its place", "in their place", "where it was", "where they were", "in the same place", "there instead",
      "in the same spot", "in its spot", "in its space", "in its bay", "in its position", "where it used to be"};
  return kPhrases;
}

const std::vector<Relation>& relation_phrases() {
  static const std::vector<Relation> kRelations = [] {
    std::vector<Relation> out{
      {"in front of", "front"}, {"to the front of", "front"}, {"at the front of", "front"}, {"ahead of", "front"},
      {"just ahead of", "front"}, {"past", "beyond"}, {"beyond", "beyond"},
      {"further on than", "beyond"},
      {"chasing behind", "back", true}, {"following behind", "back", true}, {"behind", "back"},
      {"chasing after", "back", true}, {"chasing", "back", true}, {"following", "back", true},
      {"chases", "back", true}, {"follows", "back", true}, {"tailing", "back", true}, {"tailgating", "back", true},
      {"tailgates", "back", true}, {"trailing", "back", true}, {"on the tail of", "back", true}, {"after", "back"},
      {"chase", "back", true}, {"follow", "back", true}, {"to the left of", "left"}, {"left of", "left"},
      {"to the right of", "right"}, {"right of", "right"}, {"next to", "left"}, {"beside", "left"},
      {"alongside", "left"}, {"level with", "left"}, {"abreast of", "left"},
      {"on the other side of the road from", "opposite"}, {"across the road from", "opposite"},
      {"across the street from", "opposite"}, {"across from", "opposite"}, {"opposite", "opposite"}};
    for (auto& r : out) r.words = text::words(r.phrase);
    return out;
  }();
  return kRelations;
}

std::optional<std::string> unsupported_noun(const std::vector<std::string>& w) {
  static const char* kNouns[] = {
      "helicopter", "helicopters", "plane", "planes", "airplane", "aeroplane", "boat", "boats", "ship", "train",
      "trains", "tram", "trams", "streetcar", "streetcars", "trolley", "trolleys", "tank", "tanks", "horse", "horses",
      "sheep", "deer", "animal", "animals", "dog", "dogs", "cat", "cats", "cow", "cows", "dinosaur", "spaceship", "ufo",
      "rocket", "submarine", "saucer", "saucers", "hovercraft", "blimp", "zeppelin", "elephant", "giraffe", "unicorn",
      "dragon", "tree", "trees", "house", "houses", "building", "buildings",
      // Street furniture and the scene itself: drawn by the background, not labelled objects.
      "traffic light", "traffic lights", "traffic signal", "traffic signals", "street light", "street lights",
      "streetlight", "streetlights", "lamp post", "lamp posts", "lamppost", "lampposts", "road sign", "road signs",
      "traffic sign", "traffic signs", "signpost", "signposts", "sign", "signs", "road markings", "markings", "sky",
      "clouds", "bench", "benches", "fence", "fences", "hedge", "hedges", "bus shelter", "shop", "shops", "school"};
  // "a horse box trailer", "a boat trailer", "the school bus": a noun right before a vehicle noun
  // says what kind of vehicle, not what is added.
  static const auto kNounWords = [] {
    std::vector<std::pair<std::string, std::vector<std::string>>> out;
    for (const char* n : kNouns) out.emplace_back(n, text::words(n));
    return out;
  }();
  const auto vehicles = find_types(w);
  for (size_t i = 0; i < w.size(); ++i)
    for (const auto& [n, nw] : kNounWords) {
      if (!words_at(w, i, nw)) continue;
      const size_t end = i + nw.size();
      if (std::none_of(vehicles.begin(), vehicles.end(), [&](const TypeMention& t) {
            const bool inside = t.begin <= i && i < t.end;  // "a school bus" is a vehicle
            return (inside || (t.begin >= end && t.begin <= end + 1)) && t.type.type != "object" && !t.type.living();
          }))
        return n;
    }
  return std::nullopt;
}

}  // namespace chatsim::agents::lexicon
