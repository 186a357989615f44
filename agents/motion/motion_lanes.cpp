// The motion intent's lane words: which lane ("my lane", "the oncoming lane", "the slow lane"),
// a lane change's target, and the words that say where a turn goes or where along the road, not
// where the vehicle starts (blanked before lanes and placement are read).
#include "agents/motion/motion_lanes.hpp"

#include <algorithm>
#include <iterator>

#include "agents/language/text.hpp"

namespace chatsim::agents::motion::detail {

using text::find_phrase;
using text::has_any;

// "turns left into the side street on the left": where it goes, not where it starts (nor on
// which side it starts), so those words are blanked before lane and placement are read.
// Returns the side the target street lies on, if said ("into the side street on the left").
// "Down the side street" is a target only for a turn: "coming down the side street" drives on it.
std::optional<std::string> blank_turn_targets(Words& w, bool turning) {
  std::optional<std::string> side_said;
  for (const char* p : {"into the side street", "into a side street", "into the side road", "into the cross street",
                        "onto the side street", "onto the cross street", "down the side street", "into the street"})
    for (size_t at = find_phrase(w, p); at != std::string::npos && (turning || w[at] != "down"); at = find_phrase(w, p)) {
      size_t end = at + text::words(p).size();
      for (const char* side : {"on the left", "on the right", "to the left", "to the right", "on my left", "on my right"})
        if (find_phrase(w, side, end) == end) {
          end += text::words(side).size();
          side_said = w[end - 1];
        }
      for (size_t k = at; k < end; ++k) w[k] = "_";
    }
  return side_said;
}

std::optional<std::string> find_lane(const Words& w_in) {
  // "the wrong side of the road" is how it drives (wrong_way), not the roadside.
  Words w = w_in;
  for (const char* p : {"wrong side of the road", "wrong side", "wrong way", "my side of the road", "our side of the road",
                        "this side of the road", "my side", "our side"})
    for (size_t at = find_phrase(w, p); at != std::string::npos; at = find_phrase(w, p))
      for (size_t k = 0; k < text::words(p).size(); ++k) w[at + k] = "_";
  if (has_any(w, {"my lane", "our lane", "same lane", "ego lane", "this lane", "current lane"})) return "ego";
  if (has_any(w, {"oncoming lane", "opposite lane", "other side of the road", "opposing lane", "oncoming traffic lane",
                  "lane of oncoming", "other side", "opposite side", "other carriageway", "opposite carriageway",
                  "the other way", "opposite direction", "other direction", "opposite way", "far side",
                  "other side of the street"}))
    return "oncoming";
  if (has_any(w, {"side street", "side road", "cross street", "side streets", "crossroad", "cross road", "side lane",
                  "farm track", "dirt track", "dirt road", "track", "alley", "alleyway", "driveway", "slip lane"}))
    return "cross";
  if (has_any(w, {"on ramp", "slip road", "ramp", "merging lane", "acceleration lane", "entry lane", "lane that ends",
                  "lane which ends", "ending lane", "lane ending", "lane that merges"}))
    return "ramp";
  if (has_any(w, {"parking lane", "shoulder", "curb", "kerb", "roadside", "side of the road", "parking spot",
                  "the parking", "parking bay", "parking area", "parking spaces", "parking spots", "parking strip"}))
    return "parking";
  if (has_any(w, {"left lane", "lane to my left", "lane on the left", "lane to the left", "adjacent lane"})) return "left";
  if (has_any(w, {"right lane", "lane to my right", "lane on the right", "lane to the right"})) return "right";
  return std::nullopt;
}

// "changing into the right lane", "moves over to the left lane": a lane change whose target is
// named. The lane words then say where it goes, not where it starts, so they are blanked.
std::optional<std::string> lane_change_to(Words& w) {
  // Not "move it to the left lane" (the user moves it there) but "it moves / drifts into my lane".
  static const char* verbs[] = {"change",  "changes", "changing", "switch", "switches", "switching", "moves",
                                "moving",  "goes",    "drifts",   "drift",  "drifting", "pull",      "pulls",
                                "pulling", "merge",   "merges",   "merging", "swerve",  "swerves",   "swerving",
                                "cut",     "cuts",    "cutting"};
  static const char* links[] = {"into", "to", "onto", "over", "the", "lanes", "lane", "across"};
  for (size_t i = 0; i < w.size(); ++i) {
    if (std::find(std::begin(verbs), std::end(verbs), w[i]) == std::end(verbs)) continue;
    for (size_t j = i + 1; j + 1 < w.size() && j <= i + 5; ++j) {
      // "merging from the left lane (into mine)": it moves away from the lane it comes from.
      if (w[j] == "from" && j + 3 < w.size() && w[j + 1] == "the" && (w[j + 2] == "left" || w[j + 2] == "right") &&
          w[j + 3] == "lane") {
        const std::string side = w[j + 2] == "left" ? "right" : "left";
        for (size_t k = j; k <= j + 3; ++k) w[k] = "_";
        for (size_t k = j + 4; k + 1 < w.size() && k <= j + 6; ++k)
          if ((w[k] == "my" || w[k] == "our") && w[k + 1] == "lane") w[k] = w[k + 1] = "_";
        return "lane_change_" + side;
      }
      if ((w[j] == "left" || w[j] == "right") && w[j + 1] == "lane") {
        const std::string side = w[j];
        w[j] = w[j + 1] = "_";
        return "lane_change_" + side;
      }
      if ((w[j] == "my" || w[j] == "our") && w[j + 1] == "lane") {
        w[j] = w[j + 1] = "_";
        return std::string("lane_change_ego");
      }
      // "into the kerb lane", "over to the fast lane": the side is the road's to say (planner).
      static const std::pair<const char*, const char*> kEdges[] = {
          {"curb", "kerb"}, {"slow", "kerb"}, {"inside", "kerb"}, {"nearside", "kerb"},
          {"fast", "median"},  {"passing", "median"}, {"overtaking", "median"}, {"outside", "median"},
          {"offside", "median"}};
      for (const auto& [word, edge] : kEdges)
        if (w[j] == word && w[j + 1] == "lane") {
          w[j] = w[j + 1] = "_";
          return "lane_change_" + std::string(edge);
        }
      if (std::find(std::begin(links), std::end(links), w[j]) == std::end(links)) break;
    }
  }
  return std::nullopt;
}

// "the lane next to the median", "the slow lane": which of a direction's lanes, said by the road
// edge it lies at. The words are blanked so that "next to the median" is no vehicle to place by.
std::optional<std::string> find_lane_edge(Words& w) {
  static const char* features[] = {"median", "central reservation", "center line", "centerline", "divider",
                                   "middle of the road", "center of the road", "curb", "kerb", "sidewalk", "pavement",
                                   "edge of the road", "verge"};
  static const char* links[] = {"next to the", "nearest the", "nearest to the", "closest to the", "beside the",
                                "by the", "along the", "alongside the", "against the", "on the"};
  for (const char* f : features)
    for (const char* l : links) {
      const std::string phrase = std::string(l) + " " + f;
      const size_t at = find_phrase(w, phrase);
      // Only for a lane: "parked next to the kerb" is the parking lane's to say.
      if (at == std::string::npos || at == 0 || (w[at - 1] != "lane" && w[at - 1] != "lanes")) continue;
      for (size_t k = 0; k < text::words(phrase).size(); ++k) w[at + k] = "_";
      const std::string feature = f;
      const bool outer = feature == "curb" || feature == "kerb" || feature == "sidewalk" || feature == "pavement" ||
                         feature == "edge of the road" || feature == "verge";
      return outer ? "outer" : "inner";
    }
  // "filtering between us and the oncoming traffic", "lane splitting": riding the lane's edge by
  // the other way's traffic, going the lane's way; what it rides between is no place to start.
  for (const char* p : {"between us and", "between me and", "between my car and"})
    if (const size_t at = find_phrase(w, p); at != std::string::npos) {
      size_t end = at + text::words(p).size();
      while (end < w.size() && end < at + 8 && w[end] != "and" && w[end] != "at" && w[end] != "with") ++end;
      std::fill(w.begin() + long(at), w.begin() + long(end), "_");
      return "inner";
    }
  if (has_any(w, {"filtering", "lane splitting", "splitting lanes", "splitting the lanes", "filters", "filter"}))
    return "inner";
  // "the fast lane" says which lane, not how fast: its first word goes.
  static const std::pair<const char*, const char*> named[] = {
      {"inner lane", "inner"}, {"inside lane", "inner"},  {"fast lane", "inner"},     {"overtaking lane", "inner"},
      {"passing lane", "inner"}, {"outer lane", "outer"}, {"outside lane", "outer"}, {"slow lane", "outer"},
      {"curb lane", "outer"}, {"curbside lane", "outer"}, {"nearside lane", "outer"}, {"offside lane", "inner"}};
  for (const auto& [phrase, edge] : named)
    if (const size_t at = find_phrase(w, phrase); at != std::string::npos) {
      w[at] = "_";
      return edge;
    }
  return std::nullopt;
}

}  // namespace chatsim::agents::motion::detail
