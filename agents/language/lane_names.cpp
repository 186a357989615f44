#include "agents/language/lane_names.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <numbers>

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"

namespace chatsim::agents::language {
namespace {

struct Role {
  const char* word;   // as said before "lane"
  const char* role;
  int side;
};

constexpr Role kRoles[] = {
    {"bus", "bus", 0},         {"buses", "bus", 0},       {"turn", "turn", 0},      {"turning", "turn", 0},
    {"filter", "turn", 0},     {"left-turn", "turn", 1},  {"right-turn", "turn", -1}, {"cycle", "cycle", 0},
    {"bike", "cycle", 0},      {"bicycle", "cycle", 0},   {"tram", "tram", 0},      {"taxi", "taxi", 0},
    {"hov", "hov", 0},         {"carpool", "hov", 0}};

// Other words a map's ids may use for a place a user names ("the toll lanes" on a map of
// "booth_1" ... "booth_4"), the word itself first.
std::vector<std::string> place_words(const std::string& word) {
  static const std::vector<std::vector<std::string>> kSame{
      {"toll", "booth", "tollbooth", "plaza"}, {"pump", "fuel", "petrol"}, {"stop", "platform"},
      {"loading", "delivery", "unloading"}, {"rank", "taxi", "cab"}, {"charger", "charging", "ev"}};
  std::vector<std::string> out{word};
  for (const auto& group : kSame)
    if (std::find(group.begin(), group.end(), word) != group.end())
      for (const auto& other : group)
        if (other != word) out.push_back(other);
  return out;
}

// Id words a map may use for each role.
std::vector<std::string> id_words(const std::string& role) {
  if (role == "turn") return {"turn", "turning", "pocket", "filter"};
  if (role == "cycle") return {"cycle", "bike", "bicycle", "cycleway", "bikeway"};
  if (role == "bus") return {"bus", "busway", "buslane", "transitway"};
  if (role == "tram") return {"tram", "tramway", "streetcar"};
  if (role == "hov") return {"hov", "carpool"};
  if (role == "roundabout") return {"roundabout", "ring", "circle", "rotary", "circulatory"};
  if (role == "car_park") return {"carpark", "park", "lot", "garage"};
  if (role == "lay_by") return {"layby", "lay", "passing", "turnout", "pullout", "refuge"};
  if (role == "fuel_station") return {"station", "pump", "pumps", "fuel", "petrol", "gas", "forecourt"};
  return place_words(role);
}

// Words before "lane", "road" or "track" that say where or which, not what the lane is for: the
// interpreter reads them itself ("the left lane", "the side road", "the slip road").
bool says_where(const std::string& w) {
  static const char* kWords[] = {
      "left", "right", "middle", "center", "my", "our", "same", "this", "that", "the", "a", "an", "other", "oncoming",
      "opposite", "opposing", "fast", "slow", "inner", "outer", "inside", "outside", "overtaking", "passing", "parking",
      "ego", "next", "adjacent", "main", "side", "cross", "slip", "merging", "acceleration", "entry", "exit", "curb",
      "nearside", "offside", "hard", "emergency", "current", "wrong", "far", "near", "dirt", "country", "whole", "empty",
      "busy", "open", "closed", "each", "every", "first", "second", "third", "last", "one", "two", "three", "own", "new",
      "nearest", "closest", "narrow", "wide", "single", "double", "its", "their", "his", "her", "to", "of", "in", "on",
      "hand"};
  // "right-hand", "left-most": any part of a hyphenated word.
  size_t from = 0;
  while (from <= w.size()) {
    const size_t dash = std::min(w.find('-', from), w.size());
    const std::string part = w.substr(from, dash - from);
    if (std::any_of(std::begin(kWords), std::end(kWords), [&](const char* k) { return part == k; })) return true;
    from = dash + 1;
  }
  return false;
}

}  // namespace

std::string use_words(const std::string& use, bool lane_word) {
  if (use.starts_with("place:")) {
    std::string out = use.substr(6);
    if (const size_t hash = out.find('#'); hash != std::string::npos) out[hash] = ' ';
    return out;
  }
  if (use == "turn_left" || use == "turn_right") return use.substr(5) + (lane_word ? "-turn lane" : "-turn");
  if (use == "rail_crossing") return "level crossing";
  std::string out = use;
  std::replace(out.begin(), out.end(), '_', ' ');
  const bool a_lane = std::any_of(std::begin(kRoles), std::end(kRoles), [&](const Role& r) { return use == r.role; }) ||
                      use.starts_with("turn") || use == "closed";
  return a_lane && lane_word ? out + " lane" : out;
}

bool is_known_use(const std::string& use) {
  if (use.starts_with("turn") || use == "roundabout" || use == "car_park" || use == "lay_by" || use == "ego_turn" ||
      use == "closed" || use == "fuel_station" || use == "rail_crossing" || use.starts_with("place:"))
    return true;
  return std::any_of(std::begin(kRoles), std::end(kRoles), [&](const Role& r) { return use == r.role; });
}

namespace {

// "the closed lane", "the coned-off lane", "the lane with the cones": a lane shut by works, which
// the map does not say but the objects standing in it do (lanes_for_use).
std::optional<LaneName> closed_lane(const std::vector<std::string>& w) {
  static const std::vector<std::string_view> kShut{"closed", "blocked", "coned", "shut", "cordoned", "works",
                                                   "roadworks", "construction", "fenced", "taped"};
  const auto shut = [&](const std::string& x) { return std::find(kShut.begin(), kShut.end(), x) != kShut.end(); };
  for (size_t i = 1; i < w.size(); ++i) {
    if (w[i] != "lane" && w[i] != "lanes") continue;
    if (w[i - 1] == "off" && i >= 2 && shut(w[i - 2])) return LaneName{"closed", i - 2, i + 1};
    if (shut(w[i - 1])) return LaneName{"closed", i - 1, i + 1};
    if (i + 3 < w.size() && w[i + 1] == "with" && w[i + 2] == "the" &&
        text::has_any({w[i + 3]}, {"cones", "roadworks", "works", "barriers", "digger", "diggers"}))
      return LaneName{"closed", i, i + 4};
  }
  return std::nullopt;
}

}  // namespace

namespace {

// "at the level crossing", "waiting at the barrier", "near the tracks": where a railway crosses the
// road (rail_crossings). "The barrier" alone is an object to add or remove: a place only after a
// word saying where.
std::optional<LaneName> rail_crossing_name(const std::vector<std::string>& w) {
  for (const char* place : {"level crossing", "level crossings", "railway crossing", "railroad crossing", "rail crossing",
                            "train crossing", "grade crossing"})
    if (const size_t at = text::find_phrase(w, place); at != std::string::npos)
      return LaneName{"rail_crossing", at, at + text::words(place).size()};
  for (const char* place : {"the crossing gates", "the crossing gate", "the barriers", "the barrier", "the boom gate",
                            "the train tracks", "the railway tracks", "the railway line", "the railway", "the railroad",
                            "the rail line", "the tracks"}) {
    const size_t at = text::find_phrase(w, place);
    if (at != std::string::npos && at > 0 &&
        text::has_any({w[at - 1]}, {"at", "by", "near", "before", "to", "toward", "approaching", "for", "from"}))
      return LaneName{"rail_crossing", at, at + text::words(place).size()};
  }
  return std::nullopt;
}

}  // namespace

std::vector<Eigen::Vector2d> rail_crossings(const scene::LaneMap& map) {
  std::vector<Eigen::Vector2d> out;
  for (size_t i = 0; i < map.lanes().size(); ++i) {
    const auto& lane = map.lanes()[i];
    const bool rail = lane.type == "rail" || lane.type == "railway" || lane.type == "train" ||
                      lane.id.find("rail") != std::string::npos;
    if (!rail) continue;
    for (const auto& x : map.crossings(int(i)))
      if (map.lanes()[size_t(x.other)].type == "driving") out.push_back(map.point_at(int(i), x.s_self));
  }
  return out;
}

std::optional<LaneName> find_lane_name(const std::vector<std::string>& w) {
  if (auto shut = closed_lane(w)) return shut;
  // "the street we're turning into", "the road it turns onto": where the ego's path goes after
  // its turn in the recording.
  for (size_t i = 0; i < w.size(); ++i) {
    if (w[i] != "street" && w[i] != "road") continue;
    for (size_t j = i + 1; j + 1 < std::min(w.size(), i + 7); ++j)
      if ((w[j] == "turn" || w[j] == "turns" || w[j] == "turning") && (w[j + 1] == "into" || w[j + 1] == "onto")) {
        size_t begin = i;
        if (begin > 0 && (w[begin - 1] == "cross" || w[begin - 1] == "side")) --begin;
        if (begin > 0 && w[begin - 1] == "the") --begin;
        return LaneName{"ego_turn", begin, j + 2};
      }
  }
  // "on the roundabout", "going round the roundabout": its ring, not "at the roundabout" (a junction).
  for (size_t i = 2; i < w.size(); ++i)
    if ((w[i] == "roundabout" || w[i] == "rotary") && w[i - 1] == "the" &&
        (w[i - 2] == "on" || w[i - 2] == "round" || w[i - 2] == "around" || w[i - 2] == "in" || w[i - 2] == "onto" ||
         w[i - 2] == "circling"))
      return LaneName{"roundabout", i - 1, i + 1};
  // "in the car park", "the parking lot": an area of the map whose lanes' ids say so.
  for (const char* place : {"car park", "carpark", "parking lot", "parking garage", "car lot", "parking structure"})
    if (const size_t at = text::find_phrase(w, place); at != std::string::npos)
      return LaneName{"car_park", at, at + text::words(place).size()};
  // "at the gas station", "on the forecourt": its pumps, entry and exit, and the bays beside them.
  for (const char* place : {"gas station", "petrol station", "filling station", "service station", "fuel station",
                            "gas stations", "petrol stations", "forecourt"})
    if (const size_t at = text::find_phrase(w, place); at != std::string::npos)
      return LaneName{"fuel_station", at, at + text::words(place).size()};
  // "the busway", "on the cycleway", "along the tram tracks": a lane of that use named by one word.
  for (const auto& [place, role] : std::initializer_list<std::pair<const char*, const char*>>{
           {"busway", "bus"}, {"busways", "bus"}, {"bus only lane", "bus"}, {"cycleway", "cycle"}, {"bikeway", "cycle"},
           {"cycle path", "cycle"}, {"bike path", "cycle"}, {"tramway", "tram"}, {"tram tracks", "tram"},
           {"tram line", "tram"}})
    if (const size_t at = text::find_phrase(w, place); at != std::string::npos)
      return LaneName{role, at, at + text::words(place).size()};
  if (auto rail = rail_crossing_name(w)) return rail;
  // "in the passing place", "pull into the lay-by": a place beside the road to stop at.
  for (const char* place : {"passing place", "passing places", "passing bay", "passing bays", "lay-by", "lay-bys",
                            "layby", "laybys", "lay by", "turnout", "turnouts", "pullout", "pullouts"})
    if (const size_t at = text::find_phrase(w, place); at != std::string::npos)
      return LaneName{"lay_by", at, at + text::words(place).size()};
  for (size_t i = 1; i < w.size(); ++i) {
    // "the service road", "the farm track": a name the map's lane ids may use.
    // "the drop-off lane", "the pick-up lane": a hyphenated name the map writes as one word.
    if ((w[i] == "road" || w[i] == "track" || w[i] == "lane") && i >= 2 &&
        (w[i - 1] == "off" || w[i - 1] == "up" || w[i - 1] == "out" || w[i - 1] == "in") && !says_where(w[i - 2]))
      return LaneName{w[i - 2] + w[i - 1], i - 2, i + 1};
    // "the through lanes": a plural only after "the" ("change lanes" names none).
    const bool named_lanes = w[i] == "lanes" && i >= 2 && w[i - 2] == "the";
    if ((w[i] == "road" || w[i] == "track" || w[i] == "lane" || named_lanes) && !says_where(w[i - 1]) &&
        std::none_of(std::begin(kRoles), std::end(kRoles), [&](const Role& r) { return w[i - 1] == r.word; }) &&
        std::isalpha(static_cast<unsigned char>(w[i - 1].front())))
      return LaneName{w[i - 1], i - 1, i + 1};
    if (w[i] != "lane" && w[i] != "lanes" && w[i] != "pocket") continue;
    for (const auto& r : kRoles) {
      if (w[i - 1] != r.word) continue;
      LaneName name{r.role, i - 1, i + 1};
      int side = r.side;
      // "the left turn lane": the side comes first.
      if (name.use == "turn" && side == 0 && i >= 2 && (w[i - 2] == "left" || w[i - 2] == "right")) {
        side = w[i - 2] == "left" ? 1 : -1;
        name.begin = i - 2;
      }
      if (side != 0) name.use += side > 0 ? "_left" : "_right";
      return name;
    }
  }
  return std::nullopt;
}

std::optional<std::string> blank_junction_place(std::vector<std::string>& w) {
  static const std::pair<const char*, const char*> kWhere[] = {
      {"past", "after"},          {"after", "after"},     {"beyond", "after"},       {"before", "before"},
      {"short of", "before"},     {"this side of", "before"}, {"ahead of", "before"}, {"in front of", "before"},
      {"across", "after"}, {"over", "after"}, {"on the other side of", "after"}, {"on the far side of", "after"},
      {"near", "near"}};
  std::optional<std::string> side;
  for (const auto& [where, meaning] : kWhere)
    for (const char* place : {"the junction", "the crossing", "the intersection", "the crossroads", "the side street",
                              "the side road", "the cross street", "the lights", "the traffic lights"}) {
      const std::string phrase = std::string(where) + " " + place;
      for (size_t at = text::find_phrase(w, phrase); at != std::string::npos; at = text::find_phrase(w, phrase)) {
        for (size_t k = 0; k < text::words(phrase).size(); ++k) w[at + k] = "_";
        side = meaning;
      }
    }
  return side;
}

namespace {

// Whether `lane` runs beside the middle of parking lane `bay`, within the bay's half width + 4.5 m.
bool runs_beside(const scene::LaneMap& map, int lane, int bay) {
  const auto& b = map.lanes()[size_t(bay)];
  const auto pos = map.project(lane, map.point_at(bay, b.length() / 2));
  return pos.s > 0 && pos.s < map.lanes()[size_t(lane)].length() && std::abs(pos.lateral) < b.width / 2 + 4.5;
}

bool two_way(const scene::Lane& l) { return l.direction == scene::TrafficDirection::Both; }

// A car park the ids do not name: bays along two-way aisles and not along a road's lanes, and
// those aisles.
std::vector<int> car_park_by_shape(const scene::LaneMap& map) {
  const auto& lanes = map.lanes();
  const auto driving_beside = [&](int bay, bool aisle) {
    for (size_t i = 0; i < lanes.size(); ++i)
      if (lanes[i].type == "driving" && two_way(lanes[i]) == aisle && runs_beside(map, int(i), bay)) return true;
    return false;
  };
  std::vector<int> bays;
  for (size_t i = 0; i < lanes.size(); ++i)
    if (lanes[i].type == "parking" && driving_beside(int(i), true) && !driving_beside(int(i), false))
      bays.push_back(int(i));
  std::vector<int> out = bays;
  for (size_t i = 0; i < lanes.size(); ++i)
    if (lanes[i].type == "driving" && two_way(lanes[i]) &&
        std::any_of(bays.begin(), bays.end(), [&](int b) { return runs_beside(map, int(i), b); }))
      out.push_back(int(i));
  return out;
}

// "pumps" -> "pump": the map's ids may say either.
std::string singular(const std::string& x) {
  return x.size() > 3 && x.back() == 's' && x[x.size() - 2] != 's' ? x.substr(0, x.size() - 1) : x;
}

// The lanes a place word names ("pump", "pump#2"): ids with that word (or its singular) and, when
// a number is said, that number.
std::vector<int> lanes_of_place(const scene::LaneMap& map, const std::string& place) {
  const size_t hash = place.find('#');
  const std::string word = place.substr(0, hash);
  std::vector<int> out;
  for (const auto& said : {word, singular(word)})
    for (const auto& id_word : place_words(said))
      if (out.empty()) out = map.named(id_word);
  if (hash == std::string::npos) return out;
  const std::string number = place.substr(hash + 1);
  std::erase_if(out, [&](int l) {
    const std::string& id = map.lanes()[size_t(l)].id;
    std::string digits;
    for (const char c : id + "_") {
      if (std::isdigit(static_cast<unsigned char>(c))) {
        digits += c;
        continue;
      }
      if (digits == number) return false;
      digits.clear();
    }
    return true;
  });
  return out;
}

}  // namespace

namespace {

bool in(const std::vector<std::string_view>& list, const std::string& x) {
  return std::find(list.begin(), list.end(), x) != list.end();
}

// Whether a word may be a place the map's lane ids name ("pumps", "busway"): not a word of places
// every map has, or that other readers take ("at the front of the queue"), nor one saying where or
// which (says_where), nor a vehicle.
bool may_name_a_place(const std::string& noun) {
  static const std::vector<std::string_view> kNotAPlace{
      "front", "back", "end", "start", "beginning", "sides", "top", "bottom", "corner", "junction",
      "crossing", "intersection", "crossroads", "lights", "light", "signal", "signals", "roundabout", "road",
      "street", "lane", "lanes", "way", "rear", "edge", "queue", "line", "pavement", "sidewalk", "scene",
      "camera", "view", "moment", "time", "speed", "distance", "place", "spot", "spots", "space", "spaces", "bay",
      "bays", "bend", "curve", "hill", "lot", "park", "area", "shoulder", "median", "verge", "row", "ramp", "exit",
      "entrance", "gap", "traffic", "world", "picture", "frame", "ground", "car", "cars"};
  const bool word = noun.size() >= 3 && std::all_of(noun.begin(), noun.end(), [](char c) {
                      return std::isalpha(static_cast<unsigned char>(c));
                    });
  return word && !says_where(noun) && !in(kNotAPlace, noun) && lexicon::find_types({noun}).empty();
}

}  // namespace

std::optional<LaneName> find_beyond_place(const std::vector<std::string>& w) {
  for (const char* where : {"other side of the", "far side of the", "beyond the", "across the"}) {
    const size_t at = text::find_phrase(w, where);
    if (at == std::string::npos) continue;
    const size_t from = at + text::words(where).size();
    if (from >= w.size()) continue;
    const std::vector<std::string> rest(w.begin() + long(from) - 1, w.end());  // from "the"
    if (const auto name = find_lane_name(rest); name && name->begin <= 1)
      return LaneName{name->use, at, from - 1 + name->end};
    if (may_name_a_place(w[from])) return LaneName{"place:" + w[from], at, from + 1};
  }
  return std::nullopt;
}

std::optional<LaneName> find_place_word(const std::vector<std::string>& w) {
  static const std::vector<std::string_view> kAt{"at", "by", "near", "beside", "into", "in", "on", "to", "from", "through", "via"};
  static const std::vector<std::string_view> kFree{"free", "empty", "open", "vacant", "available", "spare"};
  const auto numbered = [&](size_t k) {  // "pump 2", "bay three"
    size_t used = 0;
    const auto n = text::number_at(w, k + 1, &used);
    return n && used == 1 && *n >= 1 && *n < 100 && *n == std::floor(*n) ? std::optional<int>(int(*n)) : std::nullopt;
  };
  for (size_t i = 0; i + 2 < w.size(); ++i) {
    if (!in(kAt, w[i]) || (w[i + 1] != "the" && !numbered(i + 1))) continue;
    size_t k = w[i + 1] == "the" ? i + 2 : i + 1;
    if (in(kFree, w[k]) && k + 1 < w.size()) ++k;
    // "at the second booth": its number before it.
    const int nth = w[i + 1] == "the" && k + 1 < w.size() ? text::ordinal_value(w[k]) : 0;
    if (nth > 0) ++k;
    const std::string& noun = w[k];
    if (!may_name_a_place(noun)) continue;
    std::string use = "place:" + noun;
    size_t end = k + 1;
    if (const auto n = numbered(k)) {
      use += "#" + std::to_string(*n);
      end = k + 2;
    } else if (nth > 0) {
      use += "#" + std::to_string(nth);
    }
    return LaneName{use, i + 1, end};
  }
  return std::nullopt;
}

std::vector<int> lanes_for_use(const scene::LaneMap& map, const std::string& use) {
  if (use == "rail_crossing") return {};  // a point on the road, not a lane to drive or stand in
  const bool turn = use.starts_with("turn");
  const int side = use == "turn_left" ? 1 : use == "turn_right" ? -1 : 0;
  std::vector<int> out;
  for (const auto& word : id_words(turn ? "turn" : use))
    for (int lane : map.named(word))
      if (std::find(out.begin(), out.end(), lane) == out.end()) out.push_back(lane);
  // A lay-by is a place to stop: of the lanes so named, those (a "passing_lane" is for driving);
  // with none named, any parking lane or shoulder.
  if (use == "lay_by") {
    std::erase_if(out, [&](int l) { return !map.lanes()[size_t(l)].for_stopping(); });
    if (out.empty())
      for (size_t i = 0; i < map.lanes().size(); ++i)
        if (map.lanes()[i].for_stopping()) out.push_back(int(i));
  }
  if (out.empty() && use == "car_park") out = car_park_by_shape(map);
  if (use == "fuel_station") {  // and the bays beside its lanes (a tanker's, a car wash's)
    const std::vector<int> named = out;
    for (size_t i = 0; i < map.lanes().size(); ++i)
      if (map.lanes()[i].for_stopping() && std::find(out.begin(), out.end(), int(i)) == out.end() &&
          std::any_of(named.begin(), named.end(), [&](int l) { return runs_beside(map, l, int(i)); }))
        out.push_back(int(i));
  }
  if (use.starts_with("place:")) return lanes_of_place(map, use.substr(6));
  // A roundabout the ids do not name: a lane whose centreline closes on itself.
  if (out.empty() && use == "roundabout")
    for (size_t i = 0; i < map.lanes().size(); ++i)
      if (map.lanes()[i].closes_on_itself()) out.push_back(int(i));
  if (!out.empty() || !turn) return out;
  for (size_t i = 0; i < map.lanes().size(); ++i) {
    const int opens = map.diverges(int(i));
    if (opens != 0 && (side == 0 || opens == side)) out.push_back(int(i));
  }
  return out;
}

namespace {

double yaw_of(const Eigen::Isometry3d& pose) { return std::atan2(pose.linear()(1, 0), pose.linear()(0, 0)); }

// Whether lane i runs beside p (within 12 m, inside its extent) along or against yaw: a lane of
// the road p is on.
bool of_the_road_at(const scene::LaneMap& map, int i, const Eigen::Vector2d& p, double yaw) {
  const auto pos = map.project(i, p);
  const double length = map.lanes()[size_t(i)].length();
  return pos.s > 0.5 && pos.s < length - 0.5 && (map.point_at(i, pos.s) - p).norm() < 12.0 &&
         std::abs(std::cos(pos.tangent_yaw - yaw)) > 0.9;
}

std::vector<int> lanes_the_ego_turns_into(const scene::Scene& scene) {
  if (scene.frames.size() < 2 || scene.lanes.empty()) return {};
  const auto& last = scene.frames.back().ego_to_world;
  const double yaw = yaw_of(last);
  const double turn = std::remainder(yaw - yaw_of(scene.frames.front().ego_to_world), 2 * std::numbers::pi);
  if (std::abs(turn) < std::numbers::pi / 4) return {};  // it does not turn within the clip
  const Eigen::Vector2d end = last.translation().head<2>();
  const Eigen::Vector2d further = end + 20.0 * Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
  std::vector<int> out;
  for (size_t i = 0; i < scene.lanes.lanes().size(); ++i)
    if (of_the_road_at(scene.lanes, int(i), end, yaw) || of_the_road_at(scene.lanes, int(i), further, yaw))
      out.push_back(int(i));
  return out;
}

// Driving lanes closed by works: those holding two or more cones or barriers, or a construction
// vehicle, at the clip's start (each counted on the driving lane whose centre it is nearest).
std::vector<int> lanes_closed_by_works(const scene::Scene& scene) {
  const auto& lanes = scene.lanes.lanes();
  std::vector<int> weight(lanes.size(), 0);
  for (const auto& o : scene.objects) {
    const bool marker =
        o.has_category_prefix("movable_object.trafficcone") || o.has_category_prefix("movable_object.barrier");
    if ((!marker && !o.has_category_prefix("vehicle.construction")) || o.track.empty()) continue;
    const Eigen::Vector2d p = o.track.front().center.head<2>();
    int best = -1;
    double best_lateral = 0;
    for (size_t i = 0; i < lanes.size(); ++i) {
      if (lanes[i].type != "driving") continue;
      const auto pos = scene.lanes.project(int(i), p);
      const double lateral = std::abs(pos.lateral);
      if (pos.s <= 0 || pos.s >= lanes[i].length() || lateral >= lanes[i].width / 2) continue;
      if (best < 0 || lateral < best_lateral) best = int(i), best_lateral = lateral;
    }
    if (best >= 0) weight[size_t(best)] += marker ? 1 : 2;
  }
  std::vector<int> out;
  for (size_t i = 0; i < lanes.size(); ++i)
    if (weight[i] >= 2) out.push_back(int(i));
  return out;
}

}  // namespace

std::vector<int> lanes_for_use(const scene::Scene& scene, const std::string& use) {
  if (use == "ego_turn") return lanes_the_ego_turns_into(scene);
  if (use == "closed") return lanes_closed_by_works(scene);
  return lanes_for_use(scene.lanes, use);
}

}  // namespace chatsim::agents::language
