#pragma once
// Where a labelled object stands on the lane map, in the words users select by: my lane, the
// left / middle / right lane of my direction, the oncoming side, a side or cross street, a
// parking lane. Computed from the lanes, so it holds on any layout (curved, one-way, divided).
#include <string>

#include <Eigen/Core>

#include "common/scene/scene.hpp"

namespace chatsim::agents::deletion {

struct LaneRelation {
  int own = -1;           // the lane it stands on (index in the lane map), -1 on none
  bool ego = false;       // the lane the ego drives in at frame 0
  bool left = false;      // leftmost lane of the ego's direction (with one lane: left and right)
  bool middle = false;    // lanes on both sides in the same direction
  bool right = false;     // rightmost lane of the ego's direction
  bool inner = false;     // the ego's direction's lane next to the other way's (the fast lane)
  bool outer = false;     // and the one farthest from it (the slow lane, by the kerb)
  bool oncoming = false;  // a lane travelled against the ego's direction
  bool cross = false;     // a lane across the ego's (side street, cross street)
  bool parking = false;   // a parking lane or bay
  bool ramp = false;      // a lane that merges into one beside it or opens off it (an on-ramp, an exit)
  bool shoulder = false;  // on no lane, beside a driving one (the hard shoulder, the verge)
  // Which half of the road: the ego's (its direction's lanes and the kerb beside them) or the far
  // one (the oncoming lanes and beyond). Neither on a side street or a one-way street's kerbs.
  bool near_side = false;
  bool far_side = false;
};

// p: the object's centre at frame 0, world frame.
LaneRelation lane_relation(const scene::Scene& scene, const Eigen::Vector2d& p);

// "The main road": "cross" where the ego's lane meets a road of more lanes than its own (a minor
// road's junction), else "road" (the ego's road, every driving lane along it).
std::string main_road(const scene::Scene& scene);

// Whether a relation has the lane word a selector asks for (ego, left, middle, right, oncoming,
// inner, outer, cross, parking, ramp, shoulder, road), or the road side (near, far).
bool has_lane(const LaneRelation& r, const std::string& lane);

}  // namespace chatsim::agents::deletion
