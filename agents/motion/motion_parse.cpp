// The offline interpreter's motion part: placement, relative placement, lane, action, speed,
// direction. Phrases are matched on normalised words; the first match of a kind wins.
#include <cmath>

#include "agents/language/text.hpp"
#include "agents/motion/motion_intent.hpp"

namespace chatsim::agents::motion {
namespace {

using text::find_phrase;
using text::has_any;
using Words = std::vector<std::string>;

bool is_self(const std::string& w) { return w == "me" || w == "us" || w == "my" || w == "our" || w == "ego" || w == "myself"; }

// "in front of the added car" -> {"the added car", front}; not "in front of me".
std::optional<RelativePlacement> find_relative(Words& w) {
  struct Pattern {
    const char* phrase;
    const char* region;
    bool chase;
  };
  static const Pattern patterns[] = {
      {"in front of", "front", false}, {"to the front of", "front", false}, {"at the front of", "front", false},
      {"ahead of", "front", false},    {"just ahead of", "front", false},   {"chasing behind", "back", true},
      {"following behind", "back", true}, {"behind", "back", false},       {"chasing after", "back", true},
      {"chasing", "back", true},       {"following", "back", true},         {"chases", "back", true},
      {"follows", "back", true},       {"tailing", "back", true},           {"after", "back", false},
      {"to the left of", "left", false}, {"left of", "left", false},        {"to the right of", "right", false},
      {"right of", "right", false},    {"next to", "left", false},          {"beside", "left", false}};
  for (const auto& p : patterns) {
    for (size_t at = find_phrase(w, p.phrase); at != std::string::npos; at = find_phrase(w, p.phrase, at + 1)) {
      const size_t after = at + text::words(p.phrase).size();
      if (after >= w.size() || is_self(w[after])) continue;
      // The reference runs to the next preposition or verb-ish word.
      size_t end = after;
      static const char* stops[] = {"and", "that", "which", "who", "driving", "moving", "going", "at", "with",
                                    "while", "on", "in", "to", "from", "fast", "slowly", "quickly", "also"};
      for (; end < w.size(); ++end) {
        bool stop = false;
        for (const char* s : stops) stop = stop || w[end] == s;
        if (stop && end > after) break;
      }
      std::string ref = text::join(w, after, end);
      if (ref.empty() || ref == "the" || ref == "traffic" || ref == "the traffic" || ref == "the road") continue;
      if (ref.rfind("the ", 0) != 0 && ref != "it" && ref != "them" && ref != "him" && ref != "her" &&
          ref.rfind("that ", 0) != 0 && ref.rfind("this ", 0) != 0)
        continue;
      RelativePlacement r{ref, p.region};
      for (size_t k = at; k < end; ++k) w[k] = "_";
      if (p.chase) r.region = "back";
      return r;
    }
  }
  return std::nullopt;
}

std::optional<std::string> find_placement(const Words& w, bool has_ahead_distance) {
  const bool left_front = has_any(w, {"left front", "front left", "ahead on the left", "ahead to the left",
                                      "ahead left", "left ahead", "forward left", "diagonally left"});
  const bool right_front = has_any(w, {"right front", "front right", "ahead on the right", "ahead to the right",
                                       "ahead right", "right ahead", "forward right", "diagonally right"});
  if (left_front) return "left_front";
  if (right_front) return "right_front";
  const bool left = has_any(w, {"my left", "our left", "left of me", "left of us", "left side", "on the left",
                                "to the left", "at the left", "left hand side", "left-hand side", "beside me on the left"});
  const bool right = has_any(w, {"my right", "our right", "right of me", "right of us", "right side", "on the right",
                                 "to the right", "at the right", "right hand side", "beside me on the right"});
  const bool back = has_any(w, {"behind me", "behind us", "behind", "at the back", "in the back", "rear",
                                "back of me", "in back of", "to the back"});
  const bool front = has_any(w, {"in front", "ahead", "front", "before me", "in my path", "up the road"});
  if (left) return has_ahead_distance ? "left_front" : "left";
  if (right) return has_ahead_distance ? "right_front" : "right";
  if (back) return "back";
  if (front) return "front";
  return std::nullopt;
}

std::optional<std::string> find_lane(const Words& w) {
  if (has_any(w, {"my lane", "our lane", "same lane", "ego lane", "this lane", "current lane"})) return "ego";
  if (has_any(w, {"oncoming lane", "opposite lane", "other side of the road", "opposing lane", "oncoming traffic lane",
                  "lane of oncoming"}))
    return "oncoming";
  if (has_any(w, {"parking lane", "shoulder", "curb", "kerb", "roadside", "side of the road", "parking spot"}))
    return "parking";
  if (has_any(w, {"left lane", "lane to my left", "lane on the left", "lane to the left", "adjacent lane"})) return "left";
  if (has_any(w, {"right lane", "lane to my right", "lane on the right", "lane to the right"})) return "right";
  return std::nullopt;
}

std::optional<std::string> find_action(const Words& w) {
  const bool lane_change = has_any(w, {"change lanes", "changes lanes", "changing lanes", "change lane",
                                       "changes lane", "changing lane", "lane change", "switch lanes",
                                       "switches lanes", "switching lanes", "merge", "merges", "merging"});
  if (lane_change) {
    const size_t at = text::find_any(w, {"change", "changes", "changing", "lane", "switch", "switches", "switching",
                                         "merge", "merges", "merging"});
    const size_t l = find_phrase(w, "left", at), r = find_phrase(w, "right", at);
    if (l != std::string::npos && (r == std::string::npos || l < r)) return "lane_change_left";
    if (r != std::string::npos) return "lane_change_right";
    return "lane_change_left";
  }
  if (has_any(w, {"cut in", "cuts in", "cutting in", "cut into", "cuts into", "cutting into", "cut off", "cuts off",
                  "cutting off", "swerve in", "swerves in", "swerving in"}))
    return "cut_in";
  if (has_any(w, {"turn left", "turns left", "turning left", "left turn", "turn to the left", "turns to the left",
                  "turning to the left", "take a left", "takes a left", "taking a left", "make a left", "makes a left",
                  "making a left", "hang a left", "go left", "goes left", "going left", "steer left", "steers left"}))
    return "turn_left";
  if (has_any(w, {"turn right", "turns right", "turning right", "right turn", "turn to the right", "turns to the right",
                  "turning to the right", "take a right", "takes a right", "taking a right", "make a right",
                  "makes a right", "making a right", "hang a right", "go right", "goes right", "going right",
                  "steer right", "steers right"}))
    return "turn_right";
  if (has_any(w, {"reverse", "reverses", "reversing", "backing up", "back up", "backs up", "backward", "backwards",
                  "in reverse", "drives back", "driving back", "rolling back", "rolls back"}))
    return "backward";
  if (has_any(w, {"parked", "park", "parks", "parking", "stopped", "stationary", "static", "standing still",
                  "not moving", "idle", "stalled", "broken down", "standing", "still", "motionless", "stops",
                  "stop"}))
    return "static";
  if (has_any(w, {"straight", "moving ahead", "driving ahead", "drive ahead", "drives ahead", "going ahead",
                  "keeps going", "moving forward", "driving forward", "drives forward", "goes ahead"}))
    return "straight";
  return std::nullopt;
}

void find_speed(const Words& w, MotionIntent& m) {
  for (const auto& q : text::quantities(w, {"km/h", "kilometers per hour", "kilometer per hour", "km per hour"})) {
    m.speed_mps = q.value / 3.6;
    return;
  }
  for (const auto& q : text::quantities(w, {"mph", "miles per hour", "mile per hour"})) {
    m.speed_mps = q.value * 0.44704;
    return;
  }
  for (const auto& q : text::quantities(w, {"m/s", "meters per second", "meter per second"})) {
    m.speed_mps = q.value;
    return;
  }
  if (has_any(w, {"faster", "speed up", "speeds up", "quicker", "accelerate", "more quickly"})) m.speed = "faster";
  else if (has_any(w, {"slower", "slow down", "slows down", "more slowly", "decelerate"})) m.speed = "slower";
  else if (has_any(w, {"fast", "quickly", "speeding", "high speed", "rapidly", "racing", "quick", "speedy", "at speed",
                       "full speed", "top speed", "rushing", "hurry"}))
    m.speed = "fast";
  else if (has_any(w, {"slow", "slowly", "crawl", "crawls", "crawling", "low speed", "leisurely", "gently"}))
    m.speed = "slow";
  else if (has_any(w, {"normal speed", "normally", "moderate speed", "average speed", "regular speed"}))
    m.speed = "normal";
}

}  // namespace

MotionIntent parse_motion(const std::string& instruction) {
  Words w = text::words(instruction);
  MotionIntent m;
  m.relative = find_relative(w);
  if (m.relative && has_any(text::words(instruction), {"chasing", "chase", "chases", "following", "follows", "tailing", "pursuing"}))
    m.chase = true;
  bool ahead_distance = false;
  for (const auto& q : text::quantities(w, {"meters", "meter", "m", "feet", "foot", "ft", "yards", "yard"})) {
    const std::string unit = w[q.end - 1];
    const double f = (unit == "feet" || unit == "foot" || unit == "ft") ? 0.3048 : (unit == "yards" || unit == "yard") ? 0.9144 : 1.0;
    m.distance_m = q.value * f;
    ahead_distance = q.end < w.size() && (w[q.end] == "ahead" || w[q.end] == "in" || w[q.end] == "forward" ||
                                          w[q.end] == "away" || w[q.end] == "down");
    break;
  }
  m.lane = find_lane(w);
  // Lane words must not also count as a side placement ("in the left lane" is not "on my left").
  Words without_lane = w;
  for (const char* p : {"left lane", "right lane", "lane on the left", "lane on the right", "lane to the left",
                        "lane to the right", "lane to my left", "lane to my right", "changes lanes to the left",
                        "change lanes to the left", "changing lanes to the left", "changes lanes to the right",
                        "change lanes to the right", "changing lanes to the right", "turn to the left",
                        "turn to the right", "turns to the left", "turns to the right", "turning to the left",
                        "turning to the right", "turn left", "turns left", "turning left", "turn right", "turns right",
                        "turning right", "left turn", "right turn", "take a left", "take a right", "makes a left",
                        "makes a right", "make a left", "make a right", "merge left", "merges left", "merging left",
                        "merge right", "merges right", "merging right", "change lanes left", "change lanes right",
                        "changes lanes left", "changes lanes right", "changing lanes left", "changing lanes right"})
    for (size_t at = find_phrase(without_lane, p); at != std::string::npos; at = find_phrase(without_lane, p))
      for (size_t k = 0; k < text::words(p).size(); ++k) without_lane[at + k] = "_";
  if (!m.relative) m.placement = find_placement(without_lane, ahead_distance);
  if (has_any(w, {"close front", "close to me", "near me", "nearby", "right in front", "just ahead", "close behind",
                  "close", "near"}))
    m.distance_word = "close";
  else if (has_any(w, {"far ahead", "far away", "in the distance", "far", "distant"}))
    m.distance_word = "far";
  m.action = find_action(w);
  find_speed(w, m);
  if (has_any(w, {"toward me", "toward us", "toward the camera", "toward the ego", "coming at me", "coming at us",
                  "oncoming", "approaching", "head-on", "head on", "in my direction", "coming toward", "heading toward",
                  "driving toward", "comes toward", "toward"}))
    m.direction = "toward";
  else if (has_any(w, {"away from me", "away from us", "driving away", "moving away", "away", "leaving"}))
    m.direction = "away";
  if (has_any(w, {"wrong way", "wrong direction", "against traffic", "against the traffic", "against the flow",
                  "ghost driver", "wrong side", "contraflow", "against the direction"}))
    m.wrong_way = true;
  if (m.action == "static") m.speed = "static";
  return m;
}

}  // namespace chatsim::agents::motion
