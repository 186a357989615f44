// The deletion agent's request as JSON (the bus payload and the openai backend's answer).
#include "agents/deletion/deletion.hpp"

#include "common/util/json_fields.hpp"

namespace chatsim::agents::deletion {
namespace {

nlohmann::json selector_json(const Selector& s) {
  nlohmann::json j{{"category", s.category}, {"noun", s.noun}, {"quantity", s.quantity}};
  if (s.quantity == "n") j["n"] = s.n;
  util::put_optional(j, "color", s.color);
  util::put_optional(j, "region", s.region);
  util::put_optional(j, "lane", s.lane);
  util::put_optional(j, "lane_use", s.lane_use);
  util::put_optional(j, "road_side", s.road_side);
  util::put_optional(j, "beyond_use", s.beyond_use);
  util::put_optional(j, "junction", s.junction);
  util::put_optional(j, "of_previous", s.of_previous);
  if (s.anchor_only) j["anchor_only"] = true;
  util::put_optional(j, "approaching", s.approaching);
  util::put_optional(j, "moving", s.moving);
  if (s.reversing) j["reversing"] = true;
  util::put_optional(j, "within_m", s.within_m);
  util::put_optional(j, "beyond_m", s.beyond_m);
  if (s.parked) j["parked"] = true;
  if (s.waiting) j["waiting"] = true;
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
  util::get_optional(j, "color", s.color);
  util::get_optional(j, "region", s.region);
  util::get_optional(j, "lane", s.lane);
  util::get_optional(j, "lane_use", s.lane_use);
  util::get_optional(j, "road_side", s.road_side);
  util::get_optional(j, "beyond_use", s.beyond_use);
  util::get_optional(j, "junction", s.junction);
  util::get_optional(j, "of_previous", s.of_previous);
  s.anchor_only = j.value("anchor_only", false);
  util::get_optional(j, "approaching", s.approaching);
  util::get_optional(j, "moving", s.moving);
  s.parked = j.value("parked", false);
  s.waiting = j.value("waiting", false);
  s.reversing = j.value("reversing", false);
  util::get_optional(j, "within_m", s.within_m);
  util::get_optional(j, "beyond_m", s.beyond_m);
  util::get_optional(j, "order", s.order);
  s.nth = j.value("nth", 1);
  return s;
}

}  // namespace

nlohmann::json to_json(const DeletionRequest& r) {
  nlohmann::json j{{"targets", nlohmann::json::array()}, {"except", nlohmann::json::array()}};
  for (const auto& s : r.targets) j["targets"].push_back(selector_json(s));
  for (const auto& s : r.except) j["except"].push_back(selector_json(s));
  util::put_optional(j, "unsupported", r.unsupported);
  return j;
}

DeletionRequest deletion_request_from_json(const nlohmann::json& j) {
  DeletionRequest r;
  for (const auto& s : j.value("targets", nlohmann::json::array())) r.targets.push_back(selector_from(s));
  for (const auto& s : j.value("except", nlohmann::json::array())) r.except.push_back(selector_from(s));
  util::get_optional(j, "unsupported", r.unsupported);
  return r;
}

}  // namespace chatsim::agents::deletion
