#include "agents/view/view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "agents/language/lane_names.hpp"
#include "agents/language/text.hpp"
#include "common/util/json_fields.hpp"

namespace chatsim::agents::view {
namespace {

using Words = std::vector<std::string>;

// The lengths a view moves by: any length short of kilometres and miles (a view moved that far
// has no range check of its own yet: "3 km up" stays not understood), and lanes (3.5 m wide).
const std::vector<std::string_view>& view_units() {
  static const std::vector<std::string_view> kUnits = [] {
    auto out = text::length_units();
    std::erase_if(out, [](std::string_view u) { return text::meters_per(u).value_or(0) >= 1000; });
    out.insert(out.end(), {"lanes", "lane"});
    return out;
  }();
  return kUnits;
}

double meters_per(const std::string& unit) {
  return unit == "lanes" || unit == "lane" ? 3.5 : text::meters_per(unit).value_or(1.0);
}

// The axis and sign a direction word means, or none.
std::optional<std::pair<int, double>> direction_word(const std::string& w) {
  if (w == "ahead" || w == "forward" || w == "forwards" || w == "front" || w == "further") return std::pair{0, 1.0};
  if (w == "back" || w == "backward" || w == "backwards" || w == "behind" || w == "rear" || w == "backs") return std::pair{0, -1.0};
  if (w == "left") return std::pair{1, 1.0};
  if (w == "right") return std::pair{1, -1.0};
  if (w == "up" || w == "upward" || w == "upwards" || w == "higher" || w == "above" || w == "raise" || w == "raised" ||
      w == "lift" || w == "elevate" || w == "raising")
    return std::pair{2, 1.0};
  if (w == "down" || w == "downward" || w == "downwards" || w == "lower" || w == "below" || w == "lowered" ||
      w == "drop" || w == "lowering")
    return std::pair{2, -1.0};
  return std::nullopt;
}

// The first direction word of the sentence, before or after its first distance, tells how the
// user writes: "forward 3 m, up 1 m" (before) or "3 m forward and 1 m up" (after). Each distance
// takes the direction on that side first, then the other, then none.
bool directions_lead(const Words& w, const std::vector<text::Quantity>& distances) {
  for (size_t i = 0; i < w.size(); ++i) {
    if (!distances.empty() && i >= distances.front().begin) return false;
    if (direction_word(w[i])) return true;
  }
  return false;
}

// "three metres up and two to the left": a bare number after a distance takes its unit.
Words with_units(Words w) {
  const auto& units = view_units();
  // "back ten metres and up one": the number after the direction word.
  for (size_t i = 1; i + 1 < w.size(); ++i) {
    size_t used = 0;
    if (w[i - 1] != "and" || !direction_word(w[i]) || !text::number_at(w, i + 1, &used) || used != 1) continue;
    if (i + 2 < w.size() && std::find(units.begin(), units.end(), w[i + 2]) != units.end()) continue;
    const auto before = text::quantities(Words(w.begin(), w.begin() + long(i)), units);
    if (!before.empty()) {
      const auto unit = text::words(before.back().unit);
      w.insert(w.begin() + long(i) + 2, unit.begin(), unit.end());
    }
  }
  for (size_t i = 1; i + 1 < w.size(); ++i) {
    size_t used = 0;
    if (w[i - 1] != "and" || !text::number_at(w, i, &used) || used != 1) continue;
    if (!direction_word(w[i + 1]) && w[i + 1] != "to") continue;
    const auto before = text::quantities(Words(w.begin(), w.begin() + long(i)), view_units());
    if (!before.empty()) {
      const auto unit = text::words(before.back().unit);
      w.insert(w.begin() + long(i) + 1, unit.begin(), unit.end());
    }
  }
  return w;
}

// "up" or "down" before a determiner is a preposition: "look down the side street", "drive 10 m
// down the road" say where, not which way the camera tilts or moves.
bool is_preposition(const Words& w, size_t i) {
  return (w[i] == "up" || w[i] == "down") && i + 1 < w.size() &&
         (w[i + 1] == "the" || w[i + 1] == "this" || w[i + 1] == "that" || w[i + 1] == "my");
}

// The turn an angle's direction word means: yaw (left positive) or pitch (up positive).
std::optional<std::pair<bool, double>> rotation_word(const Words& w, size_t i) {
  if (is_preposition(w, i)) return std::nullopt;
  if (w[i] == "left" || w[i] == "counterclockwise" || w[i] == "anticlockwise") return std::pair{false, 1.0};
  if (w[i] == "right" || w[i] == "clockwise") return std::pair{false, -1.0};
  if (w[i] == "up" || w[i] == "upward" || w[i] == "upwards") return std::pair{true, 1.0};
  if (w[i] == "down" || w[i] == "downward" || w[i] == "downwards") return std::pair{true, -1.0};
  return std::nullopt;
}

bool clause_break(const std::string& w) { return w == "and" || w == "then" || w == "but" || w == "while"; }

// Rotations: "30 degrees to the left", "look 15 degrees right", "10 degrees right and 5 up".
// Each angle takes the direction word next to it (after it first, then before it), never one
// across "and" or another angle, and that word says its axis: a pitch word elsewhere in the
// sentence does not make every angle a pitch.
void add_rotations(const Words& w, ViewChange& v) {
  const auto angles = text::quantities(w, {"degrees", "degree", "deg", "°"});
  for (size_t k = 0; k < angles.size(); ++k) {
    const auto& q = angles[k];
    std::optional<std::pair<bool, double>> dir;
    const size_t next = k + 1 < angles.size() ? angles[k + 1].begin : w.size();
    for (size_t i = q.end; i < std::min(next, q.end + 4) && !dir && !clause_break(w[i]); ++i) dir = rotation_word(w, i);
    const size_t prev = k > 0 ? angles[k - 1].end : 0;
    for (size_t i = q.begin; i-- > prev && q.begin - i <= 4 && !dir && !clause_break(w[i]);) dir = rotation_word(w, i);
    if (!dir) {
      // Unsaid direction: counter-clockwise (the mathematical sense) or up; the verb says the axis.
      Words before(w.begin() + long(prev), w.begin() + long(q.begin));
      dir = std::pair{text::has_any(before, {"tilt", "pitch", "tilted", "tilts"}), 1.0};
    }
    auto& angle = dir->first ? v.pitch_deg : v.yaw_deg;
    angle = angle.value_or(0) + dir->second * q.value;
  }
}

void add_translations(const Words& w_in, ViewChange& v) {
  Words w = w_in;
  // "2 m closer to the kerb" (right-hand traffic: the kerb is on the right), "toward the middle
  // of the road" (left).
  for (const auto& [phrase, side] : {std::pair{"closer to the curb", "right"}, std::pair{"toward the curb", "right"},
                                     std::pair{"nearer the curb", "right"}, std::pair{"closer to the sidewalk", "right"},
                                     std::pair{"toward the sidewalk", "right"}, std::pair{"toward the pavement", "right"},
                                     std::pair{"toward the middle of the road", "left"},
                                     std::pair{"toward the center of the road", "left"},
                                     std::pair{"toward the center line", "left"}, std::pair{"down the road", "ahead"},
                                     std::pair{"up the road", "ahead"}, std::pair{"down the street", "ahead"},
                                     std::pair{"up the street", "ahead"}})
    for (size_t at = text::find_phrase(w, phrase); at != std::string::npos; at = text::find_phrase(w, phrase)) {
      const size_t n = text::words(phrase).size();
      w.erase(w.begin() + long(at), w.begin() + long(at + n));
      w.insert(w.begin() + long(at), side);
    }
  // "back the camera up 5 m", "back up": the verb is the direction, "up" only its particle.
  if (!w.empty() && w[0] == "back")
    for (size_t i = 1; i < std::min<size_t>(w.size(), 4); ++i)
      if (w[i] == "up") {
        w[i] = "_";
        break;
      }
  Words wu = with_units(w);
  // "pan right 20 degrees and go 10 m ahead": the side word next to an angle is the turn's.
  for (const auto& q : text::quantities(wu, {"degrees", "degree", "deg", "°"})) {
    for (size_t i = q.begin; i-- > 0 && q.begin - i <= 2;)
      if (wu[i] == "left" || wu[i] == "right") wu[i] = "_";
    for (size_t i = q.end; i < std::min(wu.size(), q.end + 3); ++i)
      if (wu[i] == "left" || wu[i] == "right") wu[i] = "_";
  }
  const auto distances = text::quantities(wu, view_units());
  const bool lead = directions_lead(wu, distances);
  for (size_t k = 0; k < distances.size(); ++k) {
    const auto& q = distances[k];
    const double f = meters_per(q.unit);
    auto after = [&]() -> std::optional<std::pair<int, double>> {
      const size_t next_start = k + 1 < distances.size() ? distances[k + 1].begin : wu.size();
      for (size_t i = q.end; i < std::min(next_start, q.end + 4); ++i) {
        // "further back": "further" only strengthens the direction word after it.
        if ((wu[i] == "further" || wu[i] == "farther") && i + 1 < wu.size() && direction_word(wu[i + 1])) continue;
        if (is_preposition(wu, i)) continue;
        if (auto d = direction_word(wu[i])) return d;
      }
      return std::nullopt;
    };
    auto before = [&]() -> std::optional<std::pair<int, double>> {
      const size_t prev_end = k > 0 ? distances[k - 1].end : 0;
      for (size_t i = q.begin; i-- > prev_end && q.begin - i <= 5;)
        if (auto d = direction_word(wu[i]); d && !is_preposition(wu, i)) return d;
      return std::nullopt;
    };
    auto dir = lead ? before() : after();
    if (!dir) dir = lead ? after() : before();
    if (!dir) continue;
    if (!v.translation_m) v.translation_m = std::array<double, 3>{0, 0, 0};
    (*v.translation_m)[size_t(dir->first)] += dir->second * q.value * f;
  }
}

}  // namespace

ViewChange parse_view(const std::string& instruction) {
  const Words w = text::words(instruction);
  ViewChange v;
  if (text::has_any(w, {"reset the view", "original view", "reset view", "reset the camera", "default view"})) v.reset = true;
  add_rotations(w, v);
  add_translations(w, v);
  // "over to the oncoming lane", "into the left lane": a lane of the map, found with the scene.
  for (const auto& [phrase, lane] : {std::pair{"oncoming lane", "oncoming"}, std::pair{"opposite lane", "oncoming"},
                                     std::pair{"other side of the road", "oncoming"}, std::pair{"left lane", "left"},
                                     std::pair{"right lane", "right"}, std::pair{"parking lane", "parking"},
                                     std::pair{"overtaking lane", "inner"}, std::pair{"fast lane", "inner"},
                                     std::pair{"passing lane", "inner"}, std::pair{"slow lane", "outer"},
                                     std::pair{"curb lane", "outer"}, std::pair{"other lane", "other"}})
    if (const size_t at = text::find_phrase(w, phrase);
        at != std::string::npos && at >= 2 && (w[at - 1] == "the" || w[at - 1] == "an") &&
        text::has_any({w[at - 2]}, {"to", "into", "in", "onto", "from"}))
      v.to_lane = lane;
  // "into the bus lane": a lane named by its use.
  if (const auto name = language::find_lane_name(w);
      name && name->begin >= 2 && w[name->begin - 1] == "the" &&
      text::has_any({w[name->begin - 2]}, {"to", "into", "in", "onto", "from"}))
    v.to_lane = name->use;
  // "forward to the cross street", "up to the junction": as far as the first junction ahead.
  if (!v.translation_m || (*v.translation_m)[0] == 0)
    for (const char* to : {"to the", "up to the", "as far as the", "into the"})
      for (const char* place : {"junction", "crossing", "intersection", "crossroads", "cross street", "cross road",
                                "cross aisle", "side street", "side road", "corner", "turn off", "turnoff"})
        if (text::has_any(w, {std::string(to) + " " + place}) && !text::has_any(w, {"lane", "lanes"}))
          v.to_junction = true;
  // The kerb's side is the road's to say: the sideways part said by it waits for the scene.
  if (v.translation_m && (*v.translation_m)[1] != 0 &&
      text::has_any(w, {"curb", "sidewalk", "pavement", "middle of the road", "center of the road", "center line"})) {
    v.toward_kerb_m = -(*v.translation_m)[1];
    (*v.translation_m)[1] = 0;
  }
  // "turn the camera to face left", "look right": a quarter turn when no angle is given.
  if (!v.yaw_deg && !v.translation_m) {
    for (const auto& [side, yaw] : {std::pair{"left", 90.0}, std::pair{"right", -90.0}})
      for (const char* verb : {"face", "facing", "look", "looking", "point", "pointing"})
        for (const char* link : {" ", " to the ", " the "})
          if (text::has_any(w, {std::string(verb) + link + side})) v.yaw_deg = yaw;
    // "turn the view to face the shops on the right": what it faces lies on that side.
    const size_t faces = text::find_any(w, {"face", "facing", "look at", "looking at", "point at", "pointing at"});
    const Words after(w.begin() + long(std::min(faces, w.size())), w.end());
    if (!v.yaw_deg && text::has_any(after, {"on the left", "on my left", "on our left", "to the left", "to my left"}))
      v.yaw_deg = 90;
    else if (!v.yaw_deg &&
             text::has_any(after, {"on the right", "on my right", "on our right", "to the right", "to my right"}))
      v.yaw_deg = -90;
  }
  // "turn the view around", "look behind": half a turn when no angle is given.
  if (!v.yaw_deg && text::has_any(w, {"turn around", "turn the view around", "turn the camera around", "look behind",
                                      "look back", "look backward", "look backwards", "face backward", "face backwards",
                                      "facing backward", "facing backwards", "look the other way", "face the other way",
                                      "rear view", "rearward", "view around", "camera around", "about face"}))
    v.yaw_deg = 180;
  if (text::has_any(w, {"ego", "drive", "drives", "driving", "i drive", "we drive", "crawl", "cruise", "roll", "go"}) &&
      !text::has_any(w, {"camera", "view", "viewpoint"})) {
    if (text::has_any(w, {"slowly", "slow", "crawl"})) v.ego_motion = "slow";
    else if (text::has_any(w, {"fast", "quickly", "speed", "rapidly", "faster"})) v.ego_motion = "fast";
    else if (text::has_any(w, {"stop", "stops", "stand still", "stationary", "static", "not move"})) v.ego_motion = "none";
    else if (text::has_any(w, {"ahead", "forward", "drive", "drives"})) v.ego_motion = "slow";
  }
  return v;
}

nlohmann::json to_json(const ViewChange& v) {
  nlohmann::json j = nlohmann::json::object();
  util::put_optional(j, "translation_m", v.translation_m);
  util::put_optional(j, "yaw_deg", v.yaw_deg);
  util::put_optional(j, "pitch_deg", v.pitch_deg);
  util::put_optional(j, "ego_motion", v.ego_motion);
  util::put_optional(j, "toward_kerb_m", v.toward_kerb_m);
  util::put_optional(j, "to_lane", v.to_lane);
  if (v.to_junction) j["to_junction"] = true;
  if (v.reset) j["reset"] = true;
  return j;
}

ViewChange view_change_from_json(const nlohmann::json& j) {
  ViewChange v;
  if (!j.is_object()) return v;
  util::get_optional(j, "translation_m", v.translation_m);
  util::get_optional(j, "yaw_deg", v.yaw_deg);
  util::get_optional(j, "pitch_deg", v.pitch_deg);
  util::get_optional(j, "ego_motion", v.ego_motion);
  util::get_optional(j, "toward_kerb_m", v.toward_kerb_m);
  util::get_optional(j, "to_lane", v.to_lane);
  v.to_junction = j.value("to_junction", false);
  v.reset = j.value("reset", false);
  return v;
}

namespace {

// Lanes running beside the ego at frame 0 (parallel, level with it): their sideways offsets.
struct LaneBeside {
  int lane;
  double lateral, along;  // along: +1 the ego's way, -1 the other way
};
std::vector<LaneBeside> lanes_beside(const scene::Scene& scene) {
  const auto& pose = scene.frames.front().ego_to_world;
  const Eigen::Vector2d ego = pose.translation().head<2>(), fwd = pose.linear().col(0).head<2>().normalized();
  const Eigen::Vector2d left(-fwd.y(), fwd.x());
  std::vector<LaneBeside> out;
  for (size_t i = 0; i < scene.lanes.lanes().size(); ++i) {
    const auto at = scene.lanes.project(int(i), ego);
    const Eigen::Vector2d p = scene.lanes.point_at(int(i), at.s) - ego;
    const double yaw = scene.lanes.travel_yaw_at(int(i), at.s);
    const double along = Eigen::Vector2d(std::cos(yaw), std::sin(yaw)).dot(fwd);
    // Not one that starts or ends well ahead or behind (a car park's aisle 25 m on), not a cross street.
    if (std::abs(p.dot(fwd)) > 10 || std::abs(along) < 0.7) continue;
    out.push_back({int(i), p.dot(left), along});
  }
  return out;
}

// Whether the road reaches from the ego to `lateral` lane by lane: no gap wider than a median.
bool contiguous(const std::vector<LaneBeside>& beside, double lateral) {
  std::vector<double> steps{0.0};
  for (const auto& b : beside)
    if (b.lateral * lateral >= 0 && std::abs(b.lateral) <= std::abs(lateral)) steps.push_back(std::abs(b.lateral));
  std::sort(steps.begin(), steps.end());
  for (size_t k = 1; k < steps.size(); ++k)
    if (steps[k] - steps[k - 1] > 8.5) return false;
  return true;
}

// The ego-frame sideways offset of the nearest lane of a kind beside the ego at frame 0.
std::optional<double> lane_offset(const scene::Scene& scene, const std::string& kind) {
  if (scene.frames.empty() || scene.lanes.empty()) return std::nullopt;
  const bool by_side = kind == "parking" || kind == "oncoming" || kind == "left" || kind == "right" || kind == "other";
  const auto of_use = by_side ? std::vector<int>{} : language::lanes_for_use(scene.lanes, kind);
  const auto beside = lanes_beside(scene);
  std::optional<double> best;
  for (const auto& b : beside) {
    const auto& lane = scene.lanes.lanes()[size_t(b.lane)];
    const bool fits = !by_side             ? std::find(of_use.begin(), of_use.end(), b.lane) != of_use.end()
                      : kind == "parking"  ? lane.type == "parking"
                      : kind == "oncoming" ? lane.type == "driving" && b.along < 0
                      // "the other lane": the nearest lane of traffic beside the ego's, either way
                      : kind == "other"    ? lane.type == "driving" && std::abs(b.lateral) > 1.5
                      : kind == "left"     ? lane.type == "driving" && b.along > 0 && b.lateral > 1.5
                                           : lane.type == "driving" && b.along > 0 && b.lateral < -1.5;
    if (fits && std::abs(b.lateral) < 20 && contiguous(beside, b.lateral) &&
        (!best || std::abs(b.lateral) < std::abs(*best)))
      best = b.lateral;
  }
  return best;
}

}  // namespace

bool keeps_left(const scene::Scene& scene) {
  const auto oncoming = lane_offset(scene, "oncoming");
  return oncoming && *oncoming < 0;
}

ViewChange resolve_on_map(ViewChange change, const scene::Scene& scene, double current_y_m) {
  if (change.toward_kerb_m) {
    if (!change.translation_m) change.translation_m = std::array<double, 3>{0, 0, 0};
    (*change.translation_m)[1] += (keeps_left(scene) ? 1 : -1) * *change.toward_kerb_m;
    change.toward_kerb_m.reset();
  }
  if (change.to_junction && !scene.frames.empty()) {
    const auto& pose = scene.frames.front().ego_to_world;
    const double yaw = std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
    if (const auto span = scene.lanes.junction_ahead(pose.translation().head<2>(), yaw)) {
      if (!change.translation_m) change.translation_m = std::array<double, 3>{0, 0, 0};
      (*change.translation_m)[0] = (span->from + span->to) / 2;
      change.to_junction = false;
    }
  }
  if (change.to_lane) {
    // The fast lane is next to the other way's traffic: on the right where traffic keeps left.
    if (change.to_lane == "inner" || change.to_lane == "outer")
      change.to_lane = (change.to_lane == "inner") != keeps_left(scene) ? "left" : "right";
    if (const auto target = lane_offset(scene, *change.to_lane)) {
      if (!change.translation_m) change.translation_m = std::array<double, 3>{0, 0, 0};
      (*change.translation_m)[1] = *target - current_y_m;
      change.to_lane.reset();
    }
  }
  return change;
}

ViewState apply(const ViewState& state, const ViewChange& c) {
  ViewState out = c.reset ? ViewState{} : state;
  if (c.translation_m)
    for (size_t i = 0; i < 3; ++i) out.translation_m[i] += (*c.translation_m)[i];
  if (c.yaw_deg) out.yaw_deg += *c.yaw_deg;
  if (c.pitch_deg) out.pitch_deg += *c.pitch_deg;
  if (c.ego_motion) out.ego_motion = *c.ego_motion;
  return out;
}

nlohmann::json to_json(const ViewState& v) {
  return {{"translation_m", v.translation_m}, {"yaw_deg", v.yaw_deg}, {"pitch_deg", v.pitch_deg},
          {"ego_motion", v.ego_motion}};
}

ViewState view_state_from_json(const nlohmann::json& j) {
  ViewState v;
  if (!j.is_object()) return v;
  v.translation_m = j.value("translation_m", v.translation_m);
  v.yaw_deg = j.value("yaw_deg", 0.0);
  v.pitch_deg = j.value("pitch_deg", 0.0);
  v.ego_motion = j.value("ego_motion", std::string("none"));
  return v;
}

double ego_speed_mps(const std::string& m) { return m == "slow" ? 3.0 : m == "fast" ? 15.0 : 0.0; }

std::vector<std::vector<Eigen::Isometry3d>> camera_poses(const scene::Scene& scene, const ViewState& v) {
  constexpr double kDeg = std::numbers::pi / 180;
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
  offset.translation() = Eigen::Vector3d(v.translation_m[0], v.translation_m[1], v.translation_m[2]);
  // Ego FLU: yaw about +z (left positive), pitch about -y (nose up positive).
  offset.linear() = (Eigen::AngleAxisd(v.yaw_deg * kDeg, Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(-v.pitch_deg * kDeg, Eigen::Vector3d::UnitY()))
                        .toRotationMatrix();
  // Ego motion: distance along the recorded path from frame 0 at the chosen speed.
  std::vector<double> path_s{0};
  for (size_t i = 1; i < scene.frames.size(); ++i)
    path_s.push_back(path_s.back() + (scene.frames[i].ego_to_world.translation() -
                                      scene.frames[i - 1].ego_to_world.translation()).norm());
  auto ego_at = [&](size_t f) -> Eigen::Isometry3d {
    if (v.ego_motion == "none" || scene.frames.size() < 2) return scene.frames[f].ego_to_world;
    const double s = ego_speed_mps(v.ego_motion) * (scene.frames[f].timestamp_s - scene.frames[0].timestamp_s);
    size_t i = 0;
    while (i + 2 < path_s.size() && path_s[i + 1] < s) ++i;
    const double seg = path_s[i + 1] - path_s[i];
    const double t = seg > 1e-9 ? (s - path_s[i]) / seg : 0.0;
    const auto& a = scene.frames[i].ego_to_world;
    const auto& b = scene.frames[i + 1].ego_to_world;
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    out.translation() = a.translation() + t * (b.translation() - a.translation());
    out.linear() = Eigen::Quaterniond(a.linear()).slerp(std::clamp(t, 0.0, 1.0), Eigen::Quaterniond(b.linear())).toRotationMatrix();
    return out;
  };
  std::vector<std::vector<Eigen::Isometry3d>> out;
  for (size_t f = 0; f < scene.frames.size(); ++f) {
    const Eigen::Isometry3d ego = ego_at(f) * offset;
    std::vector<Eigen::Isometry3d> cams;
    for (const auto& c : scene.cameras) cams.push_back(ego * c.sensor_to_ego);
    out.push_back(std::move(cams));
  }
  return out;
}

}  // namespace chatsim::agents::view
