#include "agents/language/lexicon.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "agents/language/text.hpp"

namespace chatsim::agents::lexicon {
namespace {

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
      {"cone", {"cone", "movable_object.trafficcone", "movable_object.trafficcone"}},
      {"barrier", {"barrier", "movable_object.barrier", "movable_object.barrier"}},
      {"pedestrian", {"pedestrian", "human.pedestrian.adult", "human"}},
      {"object", {"object", "", ""}}};
  return t;
}

struct Noun {
  const char* phrase;
  const char* type;
  bool plural;
};

// Longest phrases first so "police car" wins over "car".
const std::vector<Noun>& nouns() {
  static const std::vector<Noun> n{
      {"police cars", "police", true},   {"police car", "police", false},     {"police vehicles", "police", true},
      {"police vehicle", "police", false}, {"cop cars", "police", true},      {"cop car", "police", false},
      {"patrol cars", "police", true},   {"patrol car", "police", false},     {"police cruiser", "police", false},
      {"squad car", "police", false},    {"fire trucks", "firetruck", true},  {"fire truck", "firetruck", false},
      {"fire engines", "firetruck", true}, {"fire engine", "firetruck", false}, {"firetrucks", "firetruck", true},
      {"firetruck", "firetruck", false}, {"traffic cones", "cone", true},     {"traffic cone", "cone", false},
      {"pickup trucks", "truck", true},  {"pickup truck", "truck", false},    {"semi trucks", "truck", true},
      {"semi truck", "truck", false},    {"delivery trucks", "truck", true},  {"delivery truck", "truck", false},
      {"sports cars", "car", true},      {"sports car", "car", false},        {"race car", "car", false},
      {"school bus", "bus", false},      {"city bus", "bus", false},          {"road barriers", "barrier", true},
      {"road barrier", "barrier", false}, {"police", "police", false},        {"cops", "police", true},
      {"cars", "car", true},             {"car", "car", false},               {"sedans", "car", true},
      {"sedan", "car", false},           {"hatchback", "car", false},         {"hatchbacks", "car", true},
      {"coupe", "car", false},           {"convertible", "car", false},       {"automobiles", "car", true},
      {"automobile", "car", false},      {"vehicles", "car", true},           {"vehicle", "car", false},
      {"suvs", "suv", true},             {"suv", "suv", false},               {"crossover", "suv", false},
      {"jeeps", "suv", true},            {"trucks", "truck", true},           {"truck", "truck", false},
      {"pickups", "truck", true},        {"pickup", "truck", false},          {"semis", "truck", true},
      {"buses", "bus", true},            {"busses", "bus", true},             {"bus", "bus", false},
      {"coaches", "bus", true},          {"coach", "bus", false},             {"minivans", "van", true},
      {"minivan", "van", false},         {"vans", "van", true},               {"van", "van", false},
      {"taxis", "taxi", true},           {"taxi", "taxi", false},             {"cabs", "taxi", true},
      {"cab", "taxi", false},            {"ambulances", "ambulance", true},   {"ambulance", "ambulance", false},
      {"motorcycles", "motorcycle", true}, {"motorcycle", "motorcycle", false}, {"motorbikes", "motorcycle", true},
      {"motorbike", "motorcycle", false}, {"scooter", "motorcycle", false},   {"bicycles", "bicycle", true},
      {"bicycle", "bicycle", false},     {"bikes", "bicycle", true},          {"bike", "bicycle", false},
      {"cones", "cone", true},           {"cone", "cone", false},             {"pylons", "cone", true},
      {"pylon", "cone", false},          {"barriers", "barrier", true},       {"barrier", "barrier", false},
      {"barricades", "barrier", true},   {"barricade", "barrier", false},     {"roadblock", "barrier", false},
      {"pedestrians", "pedestrian", true}, {"pedestrian", "pedestrian", false}, {"people", "pedestrian", true},
      {"person", "pedestrian", false},   {"persons", "pedestrian", true},    {"walkers", "pedestrian", true},
      {"objects", "object", true},       {"things", "object", true}};
  return n;
}

struct Brand {
  const char* word;
  const char* brand;
  const char* type;
};

const std::vector<Brand>& brands() {
  static const std::vector<Brand> b{
      {"porsche", "porsche", "car"},       {"tesla", "tesla", "car"},           {"mini", "mini", "car"},
      {"cooper", "mini", "car"},           {"chevrolet", "chevrolet", "car"},   {"chevy", "chevrolet", "car"},
      {"bmw", "bmw", "car"},               {"audi", "audi", "car"},             {"mercedes", "mercedes", "car"},
      {"benz", "mercedes", "car"},         {"toyota", "toyota", "car"},         {"honda", "honda", "car"},
      {"ford", "ford", "car"},             {"volkswagen", "volkswagen", "car"}, {"vw", "volkswagen", "car"},
      {"nissan", "nissan", "car"},         {"hyundai", "hyundai", "car"},       {"kia", "kia", "car"},
      {"volvo", "volvo", "car"},           {"lexus", "lexus", "car"},           {"ferrari", "ferrari", "car"},
      {"lamborghini", "lamborghini", "car"}, {"mazda", "mazda", "car"},         {"subaru", "subaru", "car"},
      {"peugeot", "peugeot", "car"},       {"renault", "renault", "car"},       {"fiat", "fiat", "car"},
      {"skoda", "skoda", "car"},           {"dodge", "dodge", "car"},           {"cadillac", "cadillac", "car"},
      {"jaguar", "jaguar", "car"},         {"bentley", "bentley", "car"},       {"maserati", "maserati", "car"},
      {"mclaren", "mclaren", "car"},       {"bugatti", "bugatti", "car"},       {"lotus", "lotus", "car"},
      {"citroen", "citroen", "car"},       {"opel", "opel", "car"},             {"buick", "buick", "car"},
      {"chrysler", "chrysler", "car"},     {"infiniti", "infiniti", "car"},     {"acura", "acura", "car"},
      {"genesis", "genesis", "car"},       {"polestar", "polestar", "car"},     {"rivian", "rivian", "truck"},
      {"jeep", "jeep", "suv"},             {"landrover", "landrover", "suv"},   {"range rover", "landrover", "suv"},
      {"land rover", "landrover", "suv"},  {"hummer", "hummer", "suv"},         {"ram", "ram", "truck"},
      {"scania", "scania", "truck"},       {"man", "man", "truck"},             {"iveco", "iveco", "truck"},
      {"kenworth", "kenworth", "truck"},   {"peterbilt", "peterbilt", "truck"}, {"harley", "harley", "motorcycle"},
      {"ducati", "ducati", "motorcycle"},  {"yamaha", "yamaha", "motorcycle"},  {"kawasaki", "kawasaki", "motorcycle"}};
  return b;
}

}  // namespace

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
    const auto nw = text::words(n.phrase);
    for (size_t at = text::find_phrase(w, n.phrase); at != std::string::npos; at = text::find_phrase(w, n.phrase, at + 1)) {
      bool free = true;
      for (size_t k = 0; k < nw.size(); ++k) free = free && !used[at + k];
      if (!free) continue;
      for (size_t k = 0; k < nw.size(); ++k) used[at + k] = true;
      out.push_back({types().at(n.type), at, at + nw.size(), n.plural});
    }
  }
  std::sort(out.begin(), out.end(), [](const TypeMention& a, const TypeMention& b) { return a.begin < b.begin; });
  return out;
}

std::vector<BrandMention> find_brands(const std::vector<std::string>& w) {
  std::vector<BrandMention> out;
  for (const auto& b : brands()) {
    const size_t n = text::words(b.word).size();
    for (size_t at = text::find_phrase(w, b.word); at != std::string::npos; at = text::find_phrase(w, b.word, at + 1)) {
      // "man" and "mini" are ordinary words too; only count them before a vehicle noun or alone as a name.
      const std::string word = b.word;
      if (word == "man" && (at + 1 >= w.size() || (w[at + 1] != "truck" && w[at + 1] != "trucks"))) continue;
      if (word == "mini" && at + 1 < w.size() && (w[at + 1] == "van" || w[at + 1] == "bus")) continue;
      if (word == "ram" && at + 1 < w.size() && w[at + 1] == "into") continue;
      bool dup = false;
      for (const auto& o : out) dup = dup || (o.begin <= at && at < o.end);
      if (!dup) out.push_back({b.brand, b.type, at, at + n});
    }
  }
  std::sort(out.begin(), out.end(), [](const BrandMention& a, const BrandMention& b) { return a.begin < b.begin; });
  return out;
}

std::optional<std::string> unsupported_noun(const std::vector<std::string>& w) {
  static const char* kNouns[] = {"helicopter", "helicopters", "plane", "planes", "airplane", "aeroplane", "boat",
                                 "boats", "ship", "train", "trains", "tram", "tank", "tanks", "horse", "horses",
                                 "dog", "dogs", "cat", "cats", "cow", "cows", "dinosaur", "spaceship", "ufo",
                                 "rocket", "submarine", "elephant", "giraffe", "unicorn", "dragon", "tree", "trees",
                                 "house", "houses", "building", "buildings"};
  for (const auto& word : w)
    for (const char* n : kNouns)
      if (word == n) return word;
  return std::nullopt;
}

}  // namespace chatsim::agents::lexicon
