#pragma once
// Lanes a user names by their use: "the bus lane", "the left-turn lane", "the cycle lane". Maps
// name such lanes in their ids (nuScenes-style maps and hand-made layouts alike); a turn lane is
// also known by its shape, a lane that opens off another before a junction.
#include <optional>
#include <string>
#include <vector>

#include "common/scene/lane_map.hpp"

namespace chatsim::agents::language {

// A lane's use as the agents pass it on: bus, turn, turn_left, turn_right, cycle, tram, taxi, hov,
// roundabout ("on the roundabout": its ring), car_park ("in the car park": the lanes of that area),
// or a word of the map's own ("service" for "the service road", "farm" for "the farm track").
struct LaneName {
  std::string use;
  size_t begin = 0;   // the words naming it, [begin, end)
  size_t end = 0;
};

// The first lane named by its use in w, if any.
std::optional<LaneName> find_lane_name(const std::vector<std::string>& w);

// "past the junction", "before the crossing", "near the lights": where along the road, by the
// first junction ahead (after, before or near), not the cross street's lane; the words are blanked.
std::optional<std::string> blank_junction_place(std::vector<std::string>& w);

// The map's lanes of that use: those whose id has the use's word; for turn lanes, with no such
// id, the lanes that open off another (on the side said). None: the map does not name it.
std::vector<int> lanes_for_use(const scene::LaneMap& map, const std::string& use);

}  // namespace chatsim::agents::language
