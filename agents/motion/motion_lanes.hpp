#pragma once
// Lane words of a motion instruction (motion_lanes.cpp), used by parse_motion.
#include <optional>
#include <string>
#include <vector>

namespace chatsim::agents::motion::detail {

using Words = std::vector<std::string>;

// "turns left into the side street on the left": the turn's target words are blanked; returns the
// side the target street lies on, if said. "down the side street" only when turning.
std::optional<std::string> blank_turn_targets(Words& w, bool turning);
// The lane said: ego, oncoming, cross, ramp, parking, left, right.
std::optional<std::string> find_lane(const Words& w);
// "changing into the right lane": lane_change_left/right/ego, its words blanked.
std::optional<std::string> lane_change_to(Words& w);
// "the lane next to the median", "the slow lane": inner or outer, its words blanked.
std::optional<std::string> find_lane_edge(Words& w);

}  // namespace chatsim::agents::motion::detail
