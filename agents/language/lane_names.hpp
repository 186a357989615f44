#pragma once
// Lanes a user names by their use: "the bus lane", "the left-turn lane", "the cycle lane". Maps
// name such lanes in their ids (nuScenes-style maps and hand-made layouts alike); a turn lane is
// also known by its shape, a lane that opens off another before a junction.
#include <optional>
#include <string>
#include <vector>

#include "common/scene/scene.hpp"

namespace chatsim::agents::language {

// A lane's use as the agents pass it on: ego_turn ("the street we turn into": the road the ego's
// path takes after its turn), bus, turn, turn_left, turn_right, cycle, tram, taxi, hov,
// roundabout ("on the roundabout": its ring), car_park ("in the car park": the lanes of that area),
// closed ("the coned-off lane": a driving lane with cones, barriers or a construction vehicle in it),
// rail_crossing ("at the level crossing": where a railway crosses the road, rail_crossings),
// fuel_station ("at the gas station": its lanes and the bays beside them), place:<word>[#n]
// (find_place_word),
// or a word of the map's own ("service" for "the service road", "farm" for "the farm track").
struct LaneName {
  std::string use;
  size_t begin = 0;   // the words naming it, [begin, end)
  size_t end = 0;
};

// A use as a user would say it, for messages: "bus lane", "car park", "pump 2"; without
// `lane_word`, "bus", "left-turn".
std::string use_words(const std::string& use, bool lane_word = true);

// Whether a use is one of the interpreter's own (bus, turn..., cycle, ego_turn, ...), as opposed
// to a word of the map's ("service", "dropoff") that only the map's lane ids can give a meaning.
bool is_known_use(const std::string& use);

// The first lane named by its use in w, if any.
std::optional<LaneName> find_lane_name(const std::vector<std::string>& w);

// "at the pumps", "at pump 2", "by the free charger": a place said by a word the map's lane ids
// may have (use "place:pump", "place:pump#2"). Weaker than a lane name: a map without such a lane
// says nothing, so callers keep the words for their other readings.
std::optional<LaneName> find_place_word(const std::vector<std::string>& w);

// "on the other side of the busway", "beyond the bus lane", "across the tram tracks": the place
// past which the objects meant stand (a lane name, or a place word as find_place_word reads it);
// [begin, end) spans the whole phrase. Roads and junctions are not places here (their readers
// take them).
std::optional<LaneName> find_beyond_place(const std::vector<std::string>& w);

// "past the junction", "before the crossing", "near the lights": where along the road, by the
// first junction ahead (after, before or near), not the cross street's lane; the words are blanked.
std::optional<std::string> blank_junction_place(std::vector<std::string>& w);

// Where a railway (a lane of type rail, or whose id says so) crosses a driving lane: the place
// "at the level crossing" names (use rail_crossing, which has no lanes of its own).
std::vector<Eigen::Vector2d> rail_crossings(const scene::LaneMap& map);

// The map's lanes of that use: those whose id has the use's word; for turn lanes, with no such
// id, the lanes that open off another (on the side said). None: the map does not name it.
std::vector<int> lanes_for_use(const scene::LaneMap& map, const std::string& use);
// As above, and ego_turn: the lanes of the road the ego drives on at the clip's end, when its
// recorded path has turned by more than 45 degrees by then (none when it has not); and closed.
std::vector<int> lanes_for_use(const scene::Scene& scene, const std::string& use);

}  // namespace chatsim::agents::language
