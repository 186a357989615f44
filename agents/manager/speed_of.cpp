// "Twice as fast as the cyclist": a speed said by another vehicle's, which only the conversation
// knows (a recorded vehicle's speed, or one added before).
#include <cmath>
#include <string>

#include "agents/manager/manager.hpp"

namespace chatsim::agents::manager {

using nlohmann::json;

void Manager::speed_of_vehicle(Conversation& c, json& intent, const std::string& self_id) {
  if (!intent.is_object() || !intent.contains("speed_of")) return;
  const std::string of = intent["speed_of"];
  const double factor = intent.value("speed_factor", 1.0);
  if (of == "ego") return;  // the planner knows the ego's speed
  intent.erase("speed_of");
  intent.erase("speed_factor");
  int self = -1;  // not itself ("as fast as the taxi" said of the taxi); a new vehicle is not listed yet
  for (size_t i = 0; i < c.added.size(); ++i)
    if (c.added[i].id == self_id) self = int(i);
  const auto anchor = find_anchor(c, of, self);
  // Not found: at least faster or slower, as said.
  const std::string word = factor > 1.01 ? "fast" : factor < 0.99 ? "slow" : "normal";
  if (!anchor) {
    c.notes.push_back("no vehicle matches '" + of + "' to take the speed of; it drives at a " + word + " speed");
    if (word != "normal") intent["speed"] = word;
    return;
  }
  const double speed = anchor->value("speed_mps", 0.0) * factor;
  // A parked vehicle's speed, however multiplied, is none: say so rather than park the new one.
  if (speed < 0.5) {
    c.notes.push_back(of + " is not moving, so its speed says nothing; it drives at a " + word + " speed");
    if (word != "normal") intent["speed"] = word;
    return;
  }
  intent["speed_mps"] = std::round(std::min(speed, 80.0) * 100) / 100;
  intent.erase("speed");
}

}  // namespace chatsim::agents::manager
