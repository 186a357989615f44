#include "agents/motion/motion_intent.hpp"

namespace chatsim::agents::motion {

void MotionIntent::merge(const MotionIntent& o) {
  if (o.placement) {
    placement = o.placement;
    relative.reset();
    if (!o.distance_m) distance_m.reset();
    if (!o.lane) lane.reset();
  }
  if (o.relative) {
    relative = o.relative;
    placement.reset();
  }
  if (o.distance_m) distance_m = o.distance_m;
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
  if (o.direction) direction = o.direction;
  if (o.wrong_way) wrong_way = o.wrong_way;
  if (o.chase) chase = o.chase;
  // "have it chase the red car": a chase is a drive, whatever stood before.
  if (o.chase.value_or(false) && !o.action && action == "static") {
    action.reset();
    if (speed == "static") speed.reset();
  }
  if (o.overtake) overtake = o.overtake;
  if (o.lane_edge) lane_edge = o.lane_edge;
}

nlohmann::json to_json(const MotionIntent& m) {
  nlohmann::json j = nlohmann::json::object();
  if (m.placement) j["placement"] = *m.placement;
  if (m.distance_m) j["distance_m"] = *m.distance_m;
  if (m.distance_word) j["distance_word"] = *m.distance_word;
  if (m.lane) j["lane"] = *m.lane;
  if (m.lane_edge) j["lane_edge"] = *m.lane_edge;
  if (m.relative) j["relative"] = {{"to", m.relative->to}, {"region", m.relative->region}};
  if (m.action) j["action"] = *m.action;
  if (m.speed) j["speed"] = *m.speed;
  if (m.speed_mps) j["speed_mps"] = *m.speed_mps;
  if (m.direction) j["direction"] = *m.direction;
  if (m.wrong_way) j["wrong_way"] = *m.wrong_way;
  if (m.chase) j["chase"] = *m.chase;
  if (m.overtake) j["overtake"] = *m.overtake;
  if (m.distance_change_m) j["distance_change_m"] = *m.distance_change_m;
  if (!m.problems.empty()) j["problems"] = m.problems;
  return j;
}

MotionIntent intent_from_json(const nlohmann::json& j) {
  MotionIntent m;
  if (!j.is_object()) return m;
  if (j.contains("placement")) m.placement = j["placement"].get<std::string>();
  if (j.contains("distance_m")) m.distance_m = j["distance_m"].get<double>();
  if (j.contains("distance_word")) m.distance_word = j["distance_word"].get<std::string>();
  if (j.contains("lane")) m.lane = j["lane"].get<std::string>();
  if (j.contains("lane_edge")) m.lane_edge = j["lane_edge"].get<std::string>();
  if (j.contains("relative"))
    m.relative = RelativePlacement{j["relative"].value("to", ""), j["relative"].value("region", "back")};
  if (j.contains("action")) m.action = j["action"].get<std::string>();
  if (j.contains("speed")) m.speed = j["speed"].get<std::string>();
  if (j.contains("speed_mps")) m.speed_mps = j["speed_mps"].get<double>();
  if (j.contains("direction")) m.direction = j["direction"].get<std::string>();
  if (j.contains("wrong_way")) m.wrong_way = j["wrong_way"].get<bool>();
  if (j.contains("chase")) m.chase = j["chase"].get<bool>();
  if (j.contains("overtake")) m.overtake = j["overtake"].get<bool>();
  if (j.contains("distance_change_m")) m.distance_change_m = j["distance_change_m"].get<double>();
  if (j.contains("problems")) m.problems = j["problems"].get<std::vector<std::string>>();
  return m;
}

}  // namespace chatsim::agents::motion
