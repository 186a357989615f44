// The deletion agent's request as JSON (the bus payload and the openai backend's answer).
#include "agents/deletion/deletion.hpp"

namespace chatsim::agents::deletion {
namespace {

nlohmann::json selector_json(const Selector& s) {
  nlohmann::json j{{"category", s.category}, {"noun", s.noun}, {"quantity", s.quantity}};
  if (s.quantity == "n") j["n"] = s.n;
  if (s.color) j["color"] = *s.color;
  if (s.region) j["region"] = *s.region;
  if (s.lane) j["lane"] = *s.lane;
  if (s.road_side) j["road_side"] = *s.road_side;
  if (s.of_previous) j["of_previous"] = *s.of_previous;
  if (s.anchor_only) j["anchor_only"] = true;
  if (s.approaching) j["approaching"] = *s.approaching;
  if (s.moving) j["moving"] = *s.moving;
  if (s.parked) j["parked"] = true;
  if (s.order) {
    j["order"] = *s.order;
    j["nth"] = s.nth;
  }
  return j;
}

Selector selector_from(const nlohmann::json& j) {
  Selector s;
  s.category = j.value("category", "vehicle");
  s.noun = j.value("noun", "object");
  s.quantity = j.value("quantity", "one");
  s.n = j.value("n", 1);
  if (j.contains("color")) s.color = j["color"].get<std::string>();
  if (j.contains("region")) s.region = j["region"].get<std::string>();
  if (j.contains("lane")) s.lane = j["lane"].get<std::string>();
  if (j.contains("road_side")) s.road_side = j["road_side"].get<std::string>();
  if (j.contains("of_previous")) s.of_previous = j["of_previous"].get<std::string>();
  s.anchor_only = j.value("anchor_only", false);
  if (j.contains("approaching")) s.approaching = j["approaching"].get<bool>();
  if (j.contains("moving")) s.moving = j["moving"].get<bool>();
  s.parked = j.value("parked", false);
  if (j.contains("order")) s.order = j["order"].get<std::string>();
  s.nth = j.value("nth", 1);
  return s;
}

}  // namespace

nlohmann::json to_json(const DeletionRequest& r) {
  nlohmann::json j{{"targets", nlohmann::json::array()}, {"except", nlohmann::json::array()}};
  for (const auto& s : r.targets) j["targets"].push_back(selector_json(s));
  for (const auto& s : r.except) j["except"].push_back(selector_json(s));
  if (r.unsupported) j["unsupported"] = *r.unsupported;
  return j;
}

DeletionRequest deletion_request_from_json(const nlohmann::json& j) {
  DeletionRequest r;
  for (const auto& s : j.value("targets", nlohmann::json::array())) r.targets.push_back(selector_from(s));
  for (const auto& s : j.value("except", nlohmann::json::array())) r.except.push_back(selector_from(s));
  if (j.contains("unsupported")) r.unsupported = j["unsupported"].get<std::string>();
  return r;
}

}  // namespace chatsim::agents::deletion
