// The offline interpreter's motion part: placement, relative placement, lane, action, speed,
// direction. Phrases are matched on normalised words; the first match of a kind wins.
#include <algorithm>
#include <cmath>
#include <iterator>

#include "agents/language/lane_names.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/motion/motion_intent.hpp"
#include "agents/motion/motion_lanes.hpp"
#include "agents/motion/motion_speed.hpp"

namespace chatsim::agents::motion {
namespace {

using text::find_phrase;
using text::has_any;
using detail::Words;
using namespace detail;

bool is_self(const std::string& w) { return w == "me" || w == "us" || w == "my" || w == "our" || w == "ego" || w == "myself"; }

// "in front of the added car" -> {"the added car", front}; not "in front of me".
std::optional<RelativePlacement> find_relative(Words& w) {
  for (const auto& p : lexicon::relation_phrases()) {
    for (size_t at = text::find_words(w, p.words); at != std::string::npos; at = text::find_words(w, p.words, at + 1)) {
      const size_t after = at + p.words.size();
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
      // "the silver car doing 60 km/h": the reference ends with its noun (and "i added").
      const Words window(w.begin() + long(after), w.begin() + long(end));
      const auto nouns = lexicon::find_types(window);
      const auto makes = lexicon::find_brands(window);
      size_t noun_end = std::string::npos;
      if (!nouns.empty()) noun_end = nouns.front().end;
      if (!makes.empty()) noun_end = std::min(noun_end, makes.front().end);
      if (noun_end != std::string::npos) {
        end = after + noun_end;
        while (end < w.size() && (w[end] == "i" || w[end] == "we" || w[end] == "you" || w[end] == "added" ||
                                  w[end] == "just" || w[end] == "one"))
          ++end;
      }
      std::string ref = text::join(w, after, end);
      if (ref.empty() || ref == "the" || ref == "traffic" || ref == "the traffic" || ref == "the road" ||
          ref == "the other" || ref == "each other" || ref == "one another" || ref == "the other one")
        continue;
      if (ref.rfind("the ", 0) != 0 && ref != "it" && ref != "them" && ref != "him" && ref != "her" &&
          ref.rfind("that ", 0) != 0 && ref.rfind("this ", 0) != 0)
        continue;
      // "next to the kerb", "behind the junction": a place on the road, not a vehicle to place by.
      const Words rw(w.begin() + long(after), w.begin() + long(end));
      if (ref.rfind("the ", 0) == 0 && !has_any(rw, {"one", "ones", "it"}) && lexicon::find_types(rw).empty() &&
          lexicon::find_brands(rw).empty() && lexicon::find_colors(rw).empty())
        continue;
      RelativePlacement r{ref, p.region};
      // "parked on the right after the silver SUV": where along the road, past it.
      if (p.phrase == "after" && has_any(w, {"parked", "park", "stopped", "standing"})) r.region = "beyond";
      for (size_t k = at; k < end; ++k) w[k] = "_";
      if (p.chase) r.region = "back";
      return r;
    }
  }
  return std::nullopt;
}

// "joining the back of the drive-thru queue", "at the end of the line at the barrier": behind the
// vehicle at that end of the queue (the deletion agent finds which), not behind the ego.
std::optional<RelativePlacement> find_queue_end(Words& w) {
  for (size_t at = 0; at + 3 < w.size(); ++at) {
    if (!has_any({w[at]}, {"back", "end", "tail", "rear"}) || w[at + 1] != "of" || w[at + 2] != "the") continue;
    size_t q = at + 3;
    while (q < w.size() && q < at + 7 && !has_any({w[q]}, {"queue", "line", "tailback"})) ++q;
    if (q >= w.size() || q >= at + 7) continue;
    size_t end = q + 1;
    if (end + 1 < w.size() && (w[end] == "at" || w[end] == "for" || w[end] == "in") && w[end + 1] == "the")
      for (end += 2; end < w.size() && end < q + 7 && !has_any({w[end]}, {"and", "with", "then", "but", "while"});)
        ++end;
    RelativePlacement r{"the vehicle at the " + text::join(w, at, end), "back"};
    std::fill(w.begin() + long(at), w.begin() + long(end), "_");
    return r;
  }
  return std::nullopt;
}

// "in its place", "where the truck was", "instead of the bus": at the start of a vehicle that
// was (or is being) removed; "removed" stands for the last one removed.
std::optional<RelativePlacement> find_place_of(Words& w) {
  for (const auto& p : lexicon::place_of_removed_phrases()) {
    const size_t at = find_phrase(w, p);
    if (at == std::string::npos) continue;
    for (size_t k = 0; k < text::words(p).size(); ++k) w[at + k] = "_";
    return RelativePlacement{"removed", "at"};
  }
  // "remove the police car and put an ambulance there": a bare "there" ending the clause.
  for (const char* tail : {"there", "there too", "there as well", "there now"}) {
    const Words t = text::words(tail);
    if (w.size() > t.size() + 1 && std::equal(t.begin(), t.end(), w.end() - long(t.size()))) {
      std::fill(w.end() - long(t.size()), w.end(), "_");
      return RelativePlacement{"removed", "at"};
    }
  }
  for (const char* p : {"where the", "in place of the", "instead of the"}) {
    const size_t at = find_phrase(w, p);
    if (at == std::string::npos) continue;
    const size_t from = at + text::words(p).size() - 1;  // keep "the"
    size_t end = from + 1;
    while (end < w.size() && w[end] != "was" && w[end] != "were" && w[end] != "and" && w[end] != "with" && end < from + 5) ++end;
    RelativePlacement r{text::join(w, from, end), "at"};
    for (size_t k = at; k < std::min(w.size(), end + 1); ++k) w[k] = "_";
    return r;
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
  const bool left = has_any(w, {"my left", "our left", "left of me", "left of us", "left side", "on the left", "from the left",
                                "from my left",
                                "to the left", "at the left", "left hand side", "left-hand side", "beside me on the left"});
  const bool right = has_any(w, {"my right", "our right", "right of me", "right of us", "right side", "on the right",
                                 "from the right", "from my right",
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


// "far" as a distance, not "the far side", "the far lane", "far left" (a side or lane said).
bool says_far(const Words& w) {
  for (size_t i = 0; i < w.size(); ++i)
    if (w[i] == "far" && (i + 1 == w.size() || !has_any({w[i + 1]}, {"side", "lane", "lanes", "curb", "pavement",
                                                                       "sidewalk", "corner", "edge", "left", "right",
                                                                       "bank"})))
      return true;
  return false;
}

std::optional<std::string> find_action(const Words& w) {
  // "takes the second exit (off the roundabout)": which exit round the ring, not a turn said.
  static const char* kOrdinals[] = {"first", "second", "third", "fourth"};
  for (size_t i = 0; i + 1 < w.size(); ++i)
    for (int k = 0; k < 4; ++k)
      if (w[i] == kOrdinals[k] && w[i + 1] == "exit") return "exit_" + std::to_string(k + 1);
  // "waiting at the junction to turn right", "about to pull out": what it will do after the
  // clip; now it stands (unless it is said to go on, "waits, then turns").
  const bool about_to_start = has_any(w, {"about to", "ready to", "preparing to"}) &&
                              has_any(w, {"pull", "leave", "set off", "turn", "go", "move", "drive", "depart", "start"});
  if ((has_any(w, {"waiting", "waits"}) || about_to_start) && !has_any(w, {"then", "before"})) return "static";
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
                  "stop", "waiting", "waits", "queuing", "queueing"}))
    return "static";
  if (has_any(w, {"straight", "moving ahead", "driving ahead", "drive ahead", "drives ahead", "going ahead",
                  "keeps going", "moving forward", "driving forward", "drives forward", "goes ahead", "drive forward",
                  "go forward", "move forward", "drive off", "drives off", "drive away", "drives away", "pull out",
                  "pulls out", "set off", "sets off", "move off", "moves off", "start moving", "start driving",
                  "get going", "pull away", "pulls away", "filtering", "lane splitting", "splitting lanes"}))
    return "straight";
  return std::nullopt;
}

}  // namespace

// The motion schema's ranges (agents/prompts/motion.schema.json).
constexpr double kMaxDistanceM = 500;
constexpr double kMaxSpeedMps = 80;

namespace {

// The first distance said, as a new distance, a change of it, or a problem; returns whether
// it was followed by "ahead" (so a side placement lies ahead on that side).
bool find_distance(const Words& w, MotionIntent& m) {
  // "twice as far away", "half the distance": a multiple of the distance it has.
  for (const auto& [phrase, factor] : {std::pair{"twice as far", 2.0}, std::pair{"double the distance", 2.0},
                                       std::pair{"three times as far", 3.0}, std::pair{"triple the distance", 3.0},
                                       std::pair{"half as far", 0.5}, std::pair{"half the distance", 0.5}})
    if (text::has_phrase(w, phrase)) {
      m.distance_factor = factor;
      return false;
    }
  // "a bit closer", "much further away", with no amount: a third nearer or farther (two thirds
  // "much" or "a lot"), of the distance it has.
  const auto amounts = text::quantities(w, text::length_units());
  const bool nearer = has_any(w, {"closer", "nearer"}), farther = has_any(w, {"further", "farther"});
  if ((nearer || farther) && amounts.empty() && !m.relative &&
      !has_any(w, {"closer to", "nearer to", "further from", "farther from"})) {
    const bool much = has_any(w, {"much", "a lot", "way", "lot"});
    m.distance_factor = nearer ? (much ? 1.0 / 3 : 2.0 / 3) : (much ? 5.0 / 3 : 4.0 / 3);
    return false;
  }
  for (const auto& q : amounts) {
    // "50 kilometers per hour" is a speed (find_speed), not a distance.
    if (q.end < w.size() && (w[q.end] == "per" || w[q.end] == "an" || w[q.end] == "a")) continue;
    const double d = q.value * text::meters_per(q.unit).value_or(1.0);
    // "10 m further away", "5 m closer": a change of the distance it has, not a new one.
    if (q.end < w.size() && (w[q.end] == "further" || w[q.end] == "farther" || w[q.end] == "closer" || w[q.end] == "nearer")) {
      m.distance_change_m = (w[q.end] == "closer" || w[q.end] == "nearer") ? -d : d;
      return false;
    }
    if (d < 0 || d > kMaxDistanceM)
      m.problems.push_back(text::join(w, q.begin, q.end) +
                           (d < 0 ? " is behind the camera"
                                  : " is farther than the " + std::to_string(int(kMaxDistanceM)) +
                                        " m a scene's lanes are planned over") +
                           ": say a distance from 0 to " + std::to_string(int(kMaxDistanceM)) + " m");
    else
      m.distance_m = d;
    return q.end < w.size() && (w[q.end] == "ahead" || w[q.end] == "in" || w[q.end] == "forward" ||
                                w[q.end] == "away" || w[q.end] == "down");
  }
  // "3 seconds ahead of me", "two seconds behind the bus", "a 2 s gap": a distance in time; not
  // "for 3 seconds" or "after 2 seconds" (when, or how long).
  for (const auto& q : text::quantities(w, {"seconds", "second", "secs", "sec", "s"})) {
    if (q.end >= w.size() || !has_any({w[q.end]}, {"ahead", "behind", "in", "back", "gap", "headway", "away"})) continue;
    if (q.begin > 0 && has_any({w[q.begin - 1]}, {"for", "after", "within", "in", "wait", "waits", "every"})) continue;
    if (q.value > 0 && q.value <= 60) m.headway_s = q.value;
    return w[q.end] == "ahead" || w[q.end] == "in" || w[q.end] == "away";
  }
  return false;
}

// The placement, read with lane and turn words blanked ("in the left lane" is not "on my left").
std::optional<std::string> placement_without_lane_words(const Words& w, bool ahead_distance) {
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
  return find_placement(without_lane, ahead_distance);
}

// "heading away", but not "70 m away" or "far away": those say how far, not which way.
bool bare_away(const Words& w) {
  for (size_t i = 0; i < w.size(); ++i)
    if (w[i] == "away" && (i == 0 || !(w[i - 1] == "m" || w[i - 1] == "meters" || w[i - 1] == "meter" ||
                                       w[i - 1] == "feet" || w[i - 1] == "ft" || w[i - 1] == "far" ||
                                       w[i - 1] == "yards" || w[i - 1] == "further" || w[i - 1] == "farther")))
      return true;
  return false;
}

// Which way it goes relative to the ego, whether against the traffic, and overtaking.
void find_direction(const Words& w, MotionIntent& m) {
  // Overtaking goes the ego's way, faster than it: from behind that is toward the ego's start,
  // from beside or ahead away from it, so only the speed is said (the lanes give the way).
  if (has_any(w, {"overtake", "overtakes", "overtaking", "passing me", "passes me", "pass me", "passing us"})) {
    m.overtake = true;
    if (!m.speed && !m.speed_mps) m.speed = "fast";
  }
  // "coming my way" is toward the ego, though "my way" alone ("going my way") is its direction.
  const bool comes_my_way = has_any(w, {"coming my way", "comes my way", "come my way", "coming our way",
                                        "comes our way", "heading my way", "headed my way", "heading our way"});
  // "the same direction as me": the ego's way; ahead of the ego that is away from it.
  // "coming up behind us", "catching up with me": from behind, toward the ego.
  const bool closes_in = has_any(w, {"coming up behind", "comes up behind", "come up behind", "catching up",
                                     "catches up", "catch up", "closing in", "closes in", "gaining on", "creeping up"});
  if (comes_my_way || closes_in)
    m.direction = "toward";
  else if (has_any(w, {"same direction as me", "same direction as us", "same way as me", "same way as us",
                  "in the same direction", "the way i am going", "my way", "same direction", "same way",
                  "going my way"}))
    m.direction = m.placement == "back" ? "toward" : "away";
  else if (has_any(w, {"toward me", "toward us", "toward the camera", "toward the ego", "coming at me", "coming at us",
                       "oncoming", "approaching", "head-on", "head on", "in my direction", "coming toward",
                       "heading toward", "driving toward", "comes toward", "racing toward", "rushing toward",
                       "speeding toward", "heading at me", "toward my car"}))
    m.direction = "toward";
  else if (has_any(w, {"away from me", "away from us", "driving away", "moving away", "leaving", "drive off", "drives off",
                       "driving off", "set off", "sets off", "pull away", "pulls away"}) || bare_away(w))
    m.direction = "away";
  // On the other side of the road, unless told otherwise, it comes toward the ego.
  else if (m.lane == "oncoming" && has_any(w, {"coming", "comes", "driving", "drives", "heading"}))
    m.direction = "toward";
  if (has_any(w, {"downhill", "down the hill", "down the slope", "down the incline", "descending"}))
    m.slope = "down";
  else if (has_any(w, {"uphill", "up the hill", "up the slope", "up the incline", "climbing"}))
    m.slope = "up";
  if (has_any(w, {"wrong way", "wrong direction", "against traffic", "against the traffic", "against the flow",
                  "ghost driver", "wrong side", "contraflow", "against the direction"}))
    m.wrong_way = true;
  // "toward me on my side of the road", "coming at us in our lane": the ego's side runs the ego's
  // way, so coming toward it there is against the traffic (and, unsaid, from ahead).
  if (m.direction == "toward" && !m.wrong_way &&
      has_any(w, {"my side of the road", "our side of the road", "my side", "our side", "my lane", "our lane",
                  "same lane", "in my lane", "this side of the road"}) &&
      m.placement != "back")
    m.wrong_way = true;
}


}  // namespace

MotionIntent parse_motion(const std::string& instruction) {
  Words w = text::words(instruction);
  MotionIntent m;
  const auto queue_end = find_queue_end(w);
  // "in the left-turn lane", "in the bus lane": a place; "left" and "turn" say no turn or side.
  if (const auto name = language::find_lane_name(w)) {
    m.lane_use = name->use;
    for (size_t k = name->begin; k < name->end; ++k) w[k] = "_";
  } else if (const auto place = language::find_place_word(w)) {
    m.lane_use = place->use;  // "at pump 2": its words stay for the other readings
  }
  const auto change_to = lane_change_to(w);  // first: "change into the kerb lane" names a target, not a start
  m.lane_edge = find_lane_edge(w);
  m.relative = queue_end ? queue_end : find_place_of(w);
  if (!m.relative) m.relative = find_relative(w);
  if (m.relative && has_any(text::words(instruction), {"chasing", "chase", "chases", "following", "follows", "follow",
                                                       "tailing", "pursuing"}))
    m.chase = true;
  const bool ahead_distance = find_distance(w, m);
  const bool turning = has_any(w, {"turn", "turns", "turning"});
  const auto target_side = blank_turn_targets(w, turning);
  const auto junction = turning ? std::nullopt : language::blank_junction_place(w);
  const bool by_junction = junction.has_value();
  if (junction && *junction != "near") m.junction = junction;
  m.lane = find_lane(w);
  if (!m.relative) m.placement = placement_without_lane_words(w, ahead_distance);
  // By a junction ahead, or "on my right just ahead": on that side ahead, not level with the ego.
  if ((by_junction || has_any(w, {"just ahead", "up ahead", "a bit ahead", "a little ahead", "slightly ahead"})) &&
      (m.placement == "left" || m.placement == "right"))
    m.placement = *m.placement + "_front";
  // "in the right lane alongside me": level with the ego, on the lane's side.
  if (!m.relative && !ahead_distance && (!m.placement || m.placement == "front") &&
      has_any(w, {"alongside me", "alongside us", "beside me", "beside us", "next to me", "next to us", "level with me",
                  "level with us", "abreast of me", "abreast of us"}))
    m.placement = m.lane == "right" || m.lane == "parking" ? "right" : "left";
  // "following me", "on my tail": behind the ego, going its way.
  if (!m.relative && (!m.placement || m.placement == "front") &&
      has_any(w, {"following me", "following us", "follows me", "follows us", "follow me", "tailing me", "tailing us",
                  "tailgating me", "tailgating us", "on my tail", "on our tail", "chasing me", "chasing us",
                  "chase me", "chase us", "chases me", "chases us", "pursue me", "pursue us", "pursuing me",
                  "pursuing us", "follow us"})) {
    m.placement = "back";
    if (!m.direction) m.direction = "toward";  // the ego's way: from behind, toward where the ego starts
    // A chase is fast: it closes on the ego (car following keeps it behind).
    if (has_any(w, {"chase", "chases", "chasing", "pursue", "pursuing"}) && !m.speed && !m.speed_mps) m.speed = "fast";
  }
  if (m.distance_factor) {  // "twice as far": how far is said by the factor
  } else if (has_any(w, {"close front", "close to me", "near me", "nearby", "right in front", "just ahead",
                         "close behind", "close", "near"}))
    m.distance_word = "close";
  else if (has_any(w, {"far end", "other end", "end of the road", "end of the street", "end of the aisle",
                       "end of the lane", "end of the car park", "end of the block"}))
    m.distance_word = "end";  // as far up the road as it is seen
  else if (has_any(w, {"far ahead", "far away", "in the distance", "distant"}) || says_far(w))
    m.distance_word = "far";
  m.action = change_to ? change_to : find_action(w);
  if (queue_end && !m.action && !m.speed && !m.speed_mps) m.action = "static";  // a queue stands
  // "turning into the side street on the left": the street's side is the turn's.
  if (!m.action && turning && target_side) m.action = "turn_" + *target_side;
  // Out of a side street onto the road: which way it turns is the road's to say (the planner's),
  // unless the user said it ("pulls out of the side street and turns right").
  // Reversing out of it stays a reverse ("a van reversing out of the side street").
  if (m.lane == "cross" && m.action != "static" && m.action != "turn_left" && m.action != "turn_right" &&
      m.action != "backward" &&
      has_any(w, {"coming out of", "pulling out of", "emerging from", "coming from", "out of the", "turning out of",
                  "joining from", "onto our road", "onto the road", "onto the main road", "join the road"}))
    m.action = "join";
  find_speed(w, m);
  find_direction(w, m);
  // "coming down the road from the right": crossing traffic, on a road across the ego's ahead,
  // driving toward the ego's path (not beside the ego, nor behind it in its lane).
  if (!m.relative && !m.lane && !m.action &&
      has_any(w, {"from the right", "from my right", "from our right", "from the left", "from my left",
                  "from our left"}) &&
      has_any(w, {"coming", "comes", "approaching", "approaches", "driving", "drives", "heading", "crossing",
                  "crosses"}) &&
      !has_any(w, {"behind", "lane", "overtake", "overtaking", "passing"})) {
    m.lane = "cross";
    if (!m.direction) m.direction = "toward";
  }
  // Moving words after "parked": it leaves (a revision "pull out and drive away" ends the parking).
  if (m.action == "static" && !has_any(w, {"about to", "ready to", "preparing to", "waiting to"}) &&
      has_any(w, {"pull out", "pulls out", "pulling out", "drive off", "drives off", "drive away", "drives away",
                  "driving away", "leave", "leaves", "set off"}))
    m.action = "straight";
  if (m.action == "static") m.speed = "static";
  if (m.speed_mps && (*m.speed_mps < 0 || *m.speed_mps > kMaxSpeedMps)) {
    m.problems.push_back("a speed of " + std::to_string(int(std::lround(*m.speed_mps * 3.6))) +
                         " km/h is outside what a road vehicle can drive here (0 to " +
                         std::to_string(int(kMaxSpeedMps * 3.6)) + " km/h)");
    m.speed_mps.reset();
  }
  return m;
}

}  // namespace chatsim::agents::motion
