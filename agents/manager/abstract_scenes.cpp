// Abstract scenes (a jam, a busy road, a road block, roadworks): many vehicles placed by one
// request, each strictly (no collision, on the lane asked for), fewer rather than wrong.
#include <algorithm>
#include <iterator>
#include <map>
#include <optional>

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/manager.hpp"

namespace chatsim::agents::manager {

using nlohmann::json;

namespace {

// "jammed with buses", "a queue of trucks": one kind of vehicle said for the whole scene (not
// "cars", "vehicles" or "traffic": those are the usual mix).
std::optional<std::string> said_kind(const std::string& text) {
  for (const auto& t : lexicon::find_types(text::words(text)))
    if (t.type.addable() && t.type.type != "car" && t.type.type != "cone" && t.type.type != "barrier")
      return t.type.type;
  return std::nullopt;
}

}  // namespace

void Manager::do_abstract(Conversation& c, const Instruction& in, Round& round) {
  static const char* mix[] = {"car", "suv", "van", "car", "car", "suv", "car", "van", "car", "car"};
  const auto one_kind = in.kind == "traffic_jam" || in.kind == "busy_road" ? said_kind(in.text) : std::nullopt;
  std::vector<std::string> kinds(std::begin(mix), std::end(mix));
  if (one_kind) std::fill(kinds.begin(), kinds.end(), *one_kind);
  static const char* colors[] = {"white", "black", "silver", "red", "blue", "gray", "white", "green", "black", "yellow"};
  int placed = 0, wanted = 0;
  std::map<std::string, int> failed;  // per place asked for
  std::string first_reason;
  auto add = [&](const std::string& what, const json& intent) {
    // Twice no free place for the same request: that place is full, and each try costs a search.
    const std::string place = intent.dump();
    if (failed[place] >= 2) return;
    ++wanted;
    const json asset_args{{"instruction", "add a " + what}};
    if (add_one(c, asset_args, intent, in.text + " (" + what + ")", round, true)) {
      ++placed;
      return;
    }
    ++failed[place];
    // One vehicle fewer is not a failure of the request; why the first did not fit is kept.
    if (first_reason.empty()) first_reason = c.unresolved.back().value("reason", "");
    c.unresolved.erase(c.unresolved.end() - 1);
  };
  // What the user said about where and how ("coming the other way", "in the right lane") holds
  // for every vehicle of the scene.
  const auto decided = call("motion", c, "decide", {{"instruction", in.text}});
  json said = decided.ok ? decided.result["intent"] : json::object();
  // "traffic coming the other way": oncoming traffic comes toward the ego.
  if (said.value("lane", "") == "oncoming" && !said.contains("direction")) said["direction"] = "toward";
  // "roadworks on the left side": a scene placed ahead takes a side word as that side ahead.
  if (said.value("placement", "") == "left" || said.value("placement", "") == "right")
    said["placement"] = said["placement"].get<std::string>() + "_front";
  const auto with_said = [&](json intent) {
    for (const char* key : {"lane", "lane_edge", "lane_use", "direction", "wrong_way", "placement", "junction"})
      if (said.contains(key)) intent[key] = said[key];
    return intent;
  };
  // Where recorded traffic in a lane would run into a queue or works close by (it cannot brake),
  // they stand further up the road, beyond where that traffic gets to in the clip: the first
  // vehicle is tried at each distance in turn, unless the user said one. The distance it fits at.
  const auto first_fit = [&](const std::string& what, const auto& at, std::optional<double> d,
                             std::initializer_list<double> further) {
    add(what, at(d));
    for (double next : further) {
      if (placed > 0 || said.contains("distance_m")) break;
      add(what, at(d = next));
    }
    return d;
  };
  const std::optional<double> said_distance =
      said.contains("distance_m") ? std::optional<double>(said["distance_m"].get<double>()) : std::nullopt;
  if (in.kind == "traffic_jam") {
    const auto queue_at = [&](std::optional<double> d) {
      json intent = with_said({{"placement", "front"}, {"speed", "slow"}, {"action", "straight"}});
      if (d) intent["distance_m"] = *d;
      return intent;
    };
    const auto d = first_fit(std::string(colors[0]) + " " + kinds[0], queue_at, said_distance, {45.0, 75.0, 105.0, 135.0});
    for (int k = placed; k < 8; ++k) add(std::string(colors[k]) + " " + kinds[k], queue_at(d));
  } else if (in.kind == "busy_road") {
    static const char* where[] = {"front", "left_front", "back", "front", "left_front", "back", "front", "left_front", "front", "back"};
    // "on my side of the road": all of it the ego's way (away ahead of it, toward it behind).
    const bool my_side = text::has_any(text::words(in.text), {"my side", "our side", "my direction", "our direction"});
    for (int k = 0; k < 10; ++k) {
      const bool behind = std::string(where[k]) == "back";
      add(std::string(colors[k]) + " " + kinds[k],
          with_said({{"placement", where[k]},
                     {"direction", my_side ? (behind ? "toward" : "away") : (k % 2 ? "toward" : "away")},
                     {"action", "straight"}}));
    }
  } else if (in.kind == "road_block") {
    // Two police cars stopped across the lanes ahead, barriers in front of them.
    const double at = said.value("distance_m", 20.0);
    for (const char* where : {"front", "left_front"})
      add("police car", with_said({{"placement", where}, {"distance_m", at}, {"action", "static"}}));
    for (int k = 0; k < 3; ++k)
      add("road barrier", with_said({{"placement", k == 1 ? "left_front" : "front"}, {"distance_m", at - 5.0 - 2.5 * (k / 2)},
                                     {"action", "static"}}));
  } else {
    const auto cone_at = [&](std::optional<double> d) {
      return with_said({{"placement", "front"}, {"distance_m", d.value_or(14.0)}, {"action", "static"}});
    };
    const double first = first_fit("traffic cone", cone_at, said_distance, {30.0, 50.0, 70.0}).value_or(14.0);
    for (int k = placed; k < 6; ++k) add(k < 4 ? "traffic cone" : "road barrier", cone_at(first + 3.0 * k));
  }
  if (placed == 0)
    c.unresolved.push_back({{"instruction", in.text},
                            {"reason", "no free place on the lanes for any vehicle" +
                                           (first_reason.empty() ? std::string() : " (" + first_reason + ")")}});
  else if (placed < wanted)
    c.notes.push_back(in.kind + ": placed " + std::to_string(placed) + " of " + std::to_string(wanted) +
                      " vehicles; the rest had no free place");
}

}  // namespace chatsim::agents::manager
