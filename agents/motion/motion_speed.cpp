// Speed words of a motion instruction: amounts with units, another vehicle's speed, speed words.
#include "agents/motion/motion_speed.hpp"

#include <algorithm>

#include "agents/language/text.hpp"

namespace chatsim::agents::motion::detail {
namespace {

using text::find_phrase;
using text::has_any;

// "twice as fast as the cyclist", "half the speed of the bus", "faster than the truck": the speed of
// another vehicle (or the ego's), times a factor. The vehicle is the words after the phrase, to
// the end of its noun phrase.
bool find_speed_of(const Words& w, MotionIntent& m) {
  static const std::pair<const char*, double> kPhrases[] = {
      {"as fast as", 1}, {"as quick as", 1}, {"as quickly as", 1}, {"as slow as", 1}, {"as slowly as", 1},
      {"the same speed as", 1}, {"same speed as", 1}, {"the speed of", 1}, {"faster than", 1.3},
      {"quicker than", 1.3}, {"slower than", 0.7}};
  for (const auto& [phrase, base] : kPhrases) {
    const size_t at = find_phrase(w, phrase);
    if (at == std::string::npos) continue;
    double factor = base;
    if (at >= 1 && (w[at - 1] == "twice" || w[at - 1] == "double")) factor = 2;
    if (at >= 1 && w[at - 1] == "half") factor = 0.5;
    if (at >= 1 && w[at - 1] == "thrice") factor = 3;
    if (at >= 2 && w[at - 1] == "times")
      if (const auto n = text::number_at(w, at - 2); n && *n > 0 && *n <= 10) factor = *n;
    size_t end = at + text::words(phrase).size();
    const size_t from = end;
    static const std::vector<std::string> kStop{"and", "but", "in", "on", "at", "behind", "ahead", "from", "into",
                                                "toward", "while", "with", "then", "so", "to", "along", "past"};
    while (end < w.size() && end - from < 5 && std::find(kStop.begin(), kStop.end(), w[end]) == kStop.end()) ++end;
    if (end == from) continue;
    const std::string target = text::join(w, from, end);
    // "faster than the traffic", "slower than everyone": no one vehicle's speed (faster, slower).
    if (text::has_any(Words(w.begin() + long(from), w.begin() + long(end)),
                      {"traffic", "everyone", "everybody", "everything", "others", "rest", "limit", "usual", "normal"}))
      return false;
    const bool ego = target == "me" || target == "us" || target == "the ego" || target == "my car" || target == "our car" ||
                     target == "ours" || target == "mine";
    m.speed_of = ego ? "ego" : target;
    m.speed_factor = factor;
    if (ego) m.speed = "ego";
    return true;
  }
  return false;
}

}  // namespace

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
  if (find_speed_of(w, m)) return;
  // "at the same speed as me", "keeping pace with us": the ego's own speed; "at the same speed"
  // with nothing else to match is the ego's too.
  // ("as fast as me", "the same speed as us": find_speed_of.)
  if (has_any(w, {"keeping pace with me", "keeping pace with us", "keeps pace with me", "keep pace with me",
                  "at my speed", "at our speed", "matching my speed", "matching our speed", "match my speed"}) ||
      (!m.relative && has_any(w, {"at the same speed", "the same speed"})))
    m.speed = "ego";
  else if (has_any(w, {"faster", "speed up", "speeds up", "quicker", "accelerate", "more quickly"})) m.speed = "faster";
  else if (has_any(w, {"slower", "slow down", "slows down", "more slowly", "decelerate"})) m.speed = "slower";
  else if (has_any(w, {"fast", "quickly", "speeding", "high speed", "rapidly", "racing", "quick", "speedy", "at speed",
                       "full speed", "top speed", "rushing", "hurry"}))
    m.speed = "fast";
  else if (has_any(w, {"slow", "slowly", "crawl", "crawls", "crawling", "low speed", "leisurely", "gently"}))
    m.speed = "slow";
  else if (has_any(w, {"normal speed", "normally", "moderate speed", "average speed", "regular speed"}))
    m.speed = "normal";
}

}  // namespace chatsim::agents::motion::detail
