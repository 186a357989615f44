#pragma once
// The deletion agent: which labelled objects an instruction means ("all cars", "the red car
// closest to me", "the second car on the left", "every vehicle except the truck").
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::agents::deletion {

struct Selector {
  std::string category = "vehicle";     // category prefix; "" selects every object
  std::string noun = "car";             // as said, for messages
  std::optional<std::string> color;     // basic colour class
  std::optional<std::string> region;    // front, back, left, right
  std::optional<std::string> lane;      // ego, left, middle, right, oncoming, cross, parking (lane_relation.hpp)
  std::optional<std::string> lane_use;  // bus, turn, turn_left, turn_right, cycle, tram, taxi, hov (lane_names.hpp)
  std::optional<std::string> road_side;  // near (my side of the road), far (across the road)
  std::optional<std::string> beyond_use;  // "on the other side of the busway": past the lanes of that use
  std::optional<std::string> junction;   // before, after: "the cars parked past the junction" (first one ahead)
  std::optional<std::string> of_previous;  // behind, front, beside, near, same_way: "... and the truck behind it"
  bool anchor_only = false;             // "closest to the police car": it places the next selector, stays
  std::optional<bool> moving;
  bool parked = false;                  // "parked": standing at the kerb, not waiting in a lane
  bool waiting = false;                 // "waiting at the lights", "in the queue": in a lane of traffic, not parked
  std::optional<bool> approaching;      // moving toward the ego ("the car coming toward us")
  bool reversing = false;               // moves backwards at some time ("the car backing out of its bay")
  std::optional<double> within_m;       // "within 16 m of me": at most this far from the ego at frame 0
  std::optional<double> beyond_m;       // "more than 30 m away": at least this far
  std::string quantity = "one";         // one, all, n
  int n = 1;
  std::optional<std::string> order;     // nearest, farthest, largest, smallest (by box volume)
  int nth = 1;                          // with order: the nth nearest/farthest
};

// What the instruction says (the "LLM" part).
struct DeletionRequest {
  std::vector<Selector> targets;
  std::vector<Selector> except;
  std::optional<std::string> unsupported;   // "helicopter": something no scene has
};
DeletionRequest parse_deletion(const std::string& instruction);
nlohmann::json to_json(const DeletionRequest& r);
DeletionRequest deletion_request_from_json(const nlohmann::json& j);

struct Selection {
  std::vector<std::string> ids;         // sorted by distance from the ego at frame 0
  std::vector<std::string> problems;    // targets that matched nothing, with why
};
// The objects selected, among those not already removed. `it`: the objects an earlier round spoke
// of (removed ones too), which "the car behind it" is placed by when no phrase before names one.
Selection select_objects(const scene::Scene& scene, const DeletionRequest& request,
                         const std::vector<std::string>& removed, const std::vector<std::string>& it = {});

std::string describe(const Selector& s);

}  // namespace chatsim::agents::deletion
