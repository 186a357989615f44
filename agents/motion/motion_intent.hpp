#pragma once
// The motion agent's configuration: where a vehicle starts and how it moves. Parsed from an
// instruction (only what the instruction says), merged over an earlier intent for revisions,
// and completed with defaults when planned.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace chatsim::agents::motion {

struct RelativePlacement {
  std::string to;        // reference as said: "it", "the added car", "the porsche"
  std::string region;    // front, back, left, right
};

struct MotionIntent {
  std::optional<std::string> placement;   // front, left_front, right_front, left, right, back
  std::optional<double> distance_m;
  std::optional<double> headway_s;          // "3 seconds ahead": a distance in time (the planner sets the metres)
  std::optional<double> distance_change_m;  // "10 m further away": added to the distance it has (revisions)
  std::optional<double> distance_factor;    // "twice as far away": times the distance it has (revisions)
  std::optional<std::string> distance_word;  // close, far, end ("at the far end of the street")
  std::optional<std::string> lane;        // ego, left, right, oncoming, parking
  std::optional<std::string> lane_use;    // bus, turn, turn_left, turn_right, cycle, tram, taxi, hov, car_park
  // "past the junction", "before the crossing": short of or beyond the first junction ahead; a
  // distance said with it counts from the junction ("20 m past the junction").
  std::optional<std::string> junction;    // before, after
  std::optional<std::string> lane_edge;   // inner (next to the centre line or median), outer (next to the kerb)
  std::optional<RelativePlacement> relative;  // region front, back, left, right, or at (its place)
  std::optional<std::string> action;      // straight, turn_left, turn_right, lane_change_left,
                                          // lane_change_right, backward, static, cut_in
  std::optional<std::string> speed;       // slow, normal, fast, faster, slower
  std::optional<double> speed_mps;
  // "twice as fast as the cyclist": the speed of that vehicle as said (the manager makes it
  // speed_mps), or "ego"; times speed_factor.
  std::optional<std::string> speed_of;
  std::optional<double> speed_factor;
  std::optional<std::string> direction;   // toward, away
  std::optional<std::string> slope;       // up, down: "coming down the hill" (which way that is, the map says)
  std::optional<bool> wrong_way;
  std::optional<bool> chase;              // "chasing", "following": match the target's speed
  std::optional<bool> overtake;           // "overtaking me": the ego's way, fast, passing it
  // Values said but outside what can be planned ("-5 m ahead", "900 km/h"), each with why;
  // the instruction is refused with these reasons instead of breaking the schema.
  std::vector<std::string> problems;

  // Fields set in `over` replace ours (a revision).
  void merge(const MotionIntent& over);
};

nlohmann::json to_json(const MotionIntent& intent);
MotionIntent intent_from_json(const nlohmann::json& j);

// The offline interpreter: what an English instruction says about motion and placement.
MotionIntent parse_motion(const std::string& instruction);

}  // namespace chatsim::agents::motion
