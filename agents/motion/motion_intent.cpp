#include "agents/motion/motion_intent.hpp"

#include "common/util/json_fields.hpp"

namespace chatsim::agents::motion {

void MotionIntent::merge(const MotionIntent& o) {
  if (o.placement) {
    placement = o.placement;
    relative.reset();
    if (!o.distance_m) distance_m.reset();
    if (!o.headway_s) headway_s.reset();
    if (!o.lane) lane.reset();
  }
  if (o.relative) {
    relative = o.relative;
    placement.reset();
  }
  if (o.distance_m) distance_m = o.distance_m, headway_s.reset();
  if (o.headway_s) headway_s = o.headway_s, distance_m.reset();
  if (o.distance_word) distance_word = o.distance_word;
  if (o.lane) lane = o.lane;
  if (o.action) action = o.action;
  // Told to move ("drive away"): it no longer stands, whatever the base said.
  if (!o.action && !o.speed && (o.direction || o.speed_mps) && action == "static") {
    action.reset();
    if (speed == "static") speed.reset();
  }
  if (o.action && *o.action != "static" && speed == "static") speed.reset();
  if (o.speed) {
    // "faster"/"slower" step from the current speed.
    const std::string cur = speed.value_or(action == "static" ? "static" : "normal");
    if (*o.speed == "faster") speed = cur == "slow" ? "normal" : "fast";
    else if (*o.speed == "slower") speed = cur == "fast" ? "normal" : "slow";
    else speed = o.speed;
    if (*o.speed != "faster" && *o.speed != "slower") speed_mps.reset();
    if (speed_mps && *o.speed == "faster") speed_mps = *speed_mps * 1.5;
    if (speed_mps && *o.speed == "slower") speed_mps = *speed_mps / 1.5;
    if (action == "static" && (*o.speed == "faster" || speed != "static")) action.reset();
  }
  if (o.speed_mps) {
    speed_mps = o.speed_mps;
    speed.reset();
  }
  if (o.speed_of || o.speed_mps || o.speed) {  // a speed said anew replaces one matched before
    speed_of = o.speed_of;
    speed_factor = o.speed_factor;
  }
  if (o.direction) direction = o.direction;
  if (o.slope) slope = o.slope;
  if (o.wrong_way) wrong_way = o.wrong_way;
  if (o.chase) chase = o.chase;
  // "have it chase the red car": a chase is a drive, whatever stood before.
  if (o.chase.value_or(false) && !o.action && action == "static") {
    action.reset();
    if (speed == "static") speed.reset();
  }
  if (o.overtake) overtake = o.overtake;
  if (o.lane_edge) lane_edge = o.lane_edge;
  if (o.lane_use) lane_use = o.lane_use;
  if (o.junction) junction = o.junction;
}

nlohmann::json to_json(const MotionIntent& m) {
  nlohmann::json j = nlohmann::json::object();
  util::put_optional(j, "placement", m.placement);
  util::put_optional(j, "distance_m", m.distance_m);
  util::put_optional(j, "headway_s", m.headway_s);
  util::put_optional(j, "distance_word", m.distance_word);
  util::put_optional(j, "lane", m.lane);
  util::put_optional(j, "lane_edge", m.lane_edge);
  util::put_optional(j, "lane_use", m.lane_use);
  util::put_optional(j, "junction", m.junction);
  if (m.relative) j["relative"] = {{"to", m.relative->to}, {"region", m.relative->region}};
  util::put_optional(j, "action", m.action);
  util::put_optional(j, "speed", m.speed);
  util::put_optional(j, "speed_mps", m.speed_mps);
  util::put_optional(j, "speed_of", m.speed_of);
  util::put_optional(j, "speed_factor", m.speed_factor);
  util::put_optional(j, "direction", m.direction);
  util::put_optional(j, "slope", m.slope);
  util::put_optional(j, "wrong_way", m.wrong_way);
  util::put_optional(j, "chase", m.chase);
  util::put_optional(j, "overtake", m.overtake);
  util::put_optional(j, "distance_change_m", m.distance_change_m);
  util::put_optional(j, "distance_factor", m.distance_factor);
  if (!m.problems.empty()) j["problems"] = m.problems;
  return j;
}

MotionIntent intent_from_json(const nlohmann::json& j) {
  MotionIntent m;
  if (!j.is_object()) return m;
  util::get_optional(j, "placement", m.placement);
  util::get_optional(j, "distance_m", m.distance_m);
  util::get_optional(j, "headway_s", m.headway_s);
  util::get_optional(j, "distance_word", m.distance_word);
  util::get_optional(j, "lane", m.lane);
  util::get_optional(j, "lane_edge", m.lane_edge);
  util::get_optional(j, "lane_use", m.lane_use);
  util::get_optional(j, "junction", m.junction);
  if (j.contains("relative"))
    m.relative = RelativePlacement{j["relative"].value("to", ""), j["relative"].value("region", "back")};
  util::get_optional(j, "action", m.action);
  util::get_optional(j, "speed", m.speed);
  util::get_optional(j, "speed_mps", m.speed_mps);
  util::get_optional(j, "speed_of", m.speed_of);
  util::get_optional(j, "speed_factor", m.speed_factor);
  util::get_optional(j, "direction", m.direction);
  util::get_optional(j, "slope", m.slope);
  util::get_optional(j, "wrong_way", m.wrong_way);
  util::get_optional(j, "chase", m.chase);
  util::get_optional(j, "overtake", m.overtake);
  util::get_optional(j, "distance_change_m", m.distance_change_m);
  util::get_optional(j, "distance_factor", m.distance_factor);
  if (j.contains("problems")) m.problems = j["problems"].get<std::vector<std::string>>();
  return m;
}

}  // namespace chatsim::agents::motion
