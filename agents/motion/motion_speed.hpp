#pragma once
// Speed words of a motion instruction (motion_speed.cpp), used by parse_motion.
#include "agents/motion/motion_intent.hpp"
#include "agents/motion/motion_lanes.hpp"

namespace chatsim::agents::motion::detail {

// The speed said: km/h, mph or m/s; another vehicle's ("twice as fast as the cyclist": speed_of and
// speed_factor) or the ego's; a word (fast, slow, faster, slower, normal).
void find_speed(const Words& w, MotionIntent& m);

}  // namespace chatsim::agents::motion::detail
