#include <algorithm>
#include <iterator>
#include <cmath>
#include <numbers>
#include <optional>

#include "agents/deletion/deletion.hpp"
#include "agents/deletion/lane_relation.hpp"
#include "agents/language/lane_names.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"

// Which recorded objects a deletion request's selectors pick in a scene.
namespace chatsim::agents::deletion {
namespace {

struct Candidate {
  const scene::ObjectTrack* object;
  Eigen::Vector2d pe;   // ego frame 0, or of the frame it comes into view
  double speed;
  LaneRelation lane;
  double yaw = 0;       // heading, in the same frame as pe
  bool reverses = false;  // moves against its heading at some time
  double d0 = 0;          // from the ego at frame 0: what "nearest" compares, all at one time
};

// Of the matches, those behind, in front of or beside `anchor` (in its own heading), nearest first.
std::vector<const Candidate*> placed_by(const std::vector<const Candidate*>& m, const Candidate& anchor,
                                        const std::string& relation) {
  std::vector<const Candidate*> out;
  const double c = std::cos(anchor.yaw), s = std::sin(anchor.yaw);
  for (const auto* x : m) {
    if (x == &anchor) continue;
    const Eigen::Vector2d d = x->pe - anchor.pe;
    const double along = c * d.x() + s * d.y(), side = -s * d.x() + c * d.y();
    const double lane_room = 3 + 0.2 * std::abs(along);  // a road may bend between them
    // Behind or ahead of a moving vehicle: in its stream, not oncoming past it.
    const bool oncoming = anchor.speed > 0.5 && x->speed > 0.5 && std::cos(x->yaw - anchor.yaw) < 0;
    if (oncoming && (relation == "behind" || relation == "front")) continue;
    const bool ok = relation == "same_way" ? std::cos(x->yaw - anchor.yaw) > 0.7 && x->speed > 0.5
                    : relation == "behind" ? (along < -1 && std::abs(side) < lane_room)
                    : relation == "front" ? (along > 1 && std::abs(side) < lane_room)
                    : relation == "near"  ? true
                                          : (std::abs(along) < 6 && std::abs(side) > 1.5 && std::abs(side) < 7);
    if (ok) out.push_back(x);
  }
  // "the bicycle and the car right behind it": in its stream of traffic, not a parked car beside
  // it (and behind a parked car, the next one parked), when there is one.
  const auto same_stream = [&](const Candidate* x) { return (x->speed > 0.5) == (anchor.speed > 0.5); };
  if (relation != "near" && relation != "same_way" && std::any_of(out.begin(), out.end(), same_stream))
    std::erase_if(out, [&](const Candidate* x) { return !same_stream(x); });
  std::sort(out.begin(), out.end(), [&](const Candidate* a, const Candidate* b) {
    return (a->pe - anchor.pe).norm() < (b->pe - anchor.pe).norm();
  });
  return out;
}

// Whether x stands close by the anchor: within 30 m along its heading and 2.5 m across (its lane).
bool right_there(const Candidate& anchor, const Candidate& x) {
  const Eigen::Vector2d d = x.pe - anchor.pe;
  const double c = std::cos(anchor.yaw), s = std::sin(anchor.yaw);
  return std::abs(c * d.x() + s * d.y()) < 30 && std::abs(-s * d.x() + c * d.y()) < 2.5;
}

bool scene_has_parking(const scene::Scene& scene) {
  const auto& lanes = scene.lanes.lanes();
  return std::any_of(lanes.begin(), lanes.end(), [](const scene::Lane& l) { return l.type == "parking"; });
}

bool matches(const Selector& s, const Candidate& c) {
  if (!s.category.empty() && !c.object->has_category_prefix(s.category)) return false;
  if (s.color && (!c.object->color_rgb || lexicon::color_class(*c.object->color_rgb) != *s.color)) return false;
  if (s.moving && (c.speed > 0.5) != *s.moving) return false;
  if (s.reversing && !c.reverses) return false;
  if ((s.within_m && c.d0 > *s.within_m) || (s.beyond_m && c.d0 < *s.beyond_m)) return false;
  if (s.lane && !has_lane(c.lane, *s.lane)) return false;
  if (s.road_side && !has_lane(c.lane, *s.road_side)) return false;
  if (s.approaching) {  // its heading points at the ego's place
    const bool toward = c.speed > 0.5 && -(std::cos(c.yaw) * c.pe.x() + std::sin(c.yaw) * c.pe.y()) > 0;
    if (toward != *s.approaching) return false;
  }
  if (s.region) {
    const double a = std::atan2(c.pe.y(), c.pe.x()) * 180 / std::numbers::pi;
    if (*s.region == "front" && !(c.pe.x() > 0 && std::abs(a) <= 60)) return false;
    if (*s.region == "back" && !(c.pe.x() < 0 && std::abs(a) >= 120)) return false;
    if (*s.region == "left" && !(c.pe.y() > 0.5)) return false;
    if (*s.region == "right" && !(c.pe.y() < -0.5)) return false;
  }
  return true;
}


// Of the matches, those `keep` accepts, if any is left: a preference, not a requirement.
template <class Keep>
void narrow_to(std::vector<const Candidate*>& m, Keep keep) {
  std::vector<const Candidate*> kept;
  std::copy_if(m.begin(), m.end(), std::back_inserter(kept), keep);
  if (!kept.empty()) m = std::move(kept);
}

// The front (or back) of a queue: those with none of the others within 12 m ahead of them (or
// behind), within 2 m to the side, along their heading. A vehicle standing alone is no queue
// while some stand in one.
void keep_queue_ends(bool head, std::vector<const Candidate*>& m) {
  const auto next_in_line = [](const Candidate* c, const Candidate* o, int way) {
    const Eigen::Vector2d fwd(std::cos(c->yaw), std::sin(c->yaw));
    const Eigen::Vector2d d = o->pe - c->pe;
    const double along = fwd.dot(d), side = std::abs(fwd.x() * d.y() - fwd.y() * d.x());
    return o != c && side < 2.0 && along * way > 0 && std::abs(along) < 12.0;
  };
  const auto all = m;
  narrow_to(m, [&](const Candidate* c) {
    return std::any_of(all.begin(), all.end(),
                       [&](const Candidate* o) { return next_in_line(c, o, 1) || next_in_line(c, o, -1); });
  });
  const auto queued = m;
  narrow_to(m, [&](const Candidate* c) {
    return std::none_of(queued.begin(), queued.end(),
                        [&](const Candidate* o) { return next_in_line(c, o, head ? 1 : -1); });
  });
}

// "parked" where the map has a kerb: not a car waiting in a lane (if any is left); "the bike"
// with no bicycle about: a motorbike is a bike too.
void widen_or_narrow(const Selector& t, const scene::Scene& scene, const std::vector<Candidate>& cands,
                     std::vector<const Candidate*>& m) {
  // "parked" where the map has a kerb to park at: not a car waiting in a lane (if any is left).
  if (t.parked && scene_has_parking(scene))
    narrow_to(m, [](const Candidate* c) {
      return !(c->lane.ego || c->lane.left || c->lane.middle || c->lane.right || c->lane.oncoming || c->lane.cross);
    });
  // "waiting at the lights": in a lane of traffic, not parked at the kerb (if any is left).
  if (t.waiting)
    narrow_to(m, [](const Candidate* c) { return c->lane.own >= 0 && !c->lane.parking && !c->lane.shoulder; });
  // "the bike" with no bicycle about: a motorbike is a bike too. "The lorry" with no truck
  // labelled: an articulated one is labelled by its trailer (nuScenes), a tipper as construction.
  const auto widen_to = [&](std::initializer_list<const char*> categories) {
    for (const char* category : categories) {
      Selector wider = t;
      wider.category = category;
      for (const auto& c : cands)
        if (matches(wider, c)) m.push_back(&c);
    }
  };
  if (m.empty() && (t.noun == "bike" || t.noun == "bikes")) widen_to({"vehicle.motorcycle"});
  // "the pickup": nuScenes labels pickups as trucks, other datasets as cars. A long, low car or a
  // short truck is one; a lorry only when nothing else fits.
  if (t.noun.find("pickup") != std::string::npos) {
    widen_to({"vehicle.car"});
    const auto pickup_sized = [](const Candidate* c) {
      const auto& size = c->object->size_lwh;
      if (c->object->has_category_prefix("vehicle.truck")) return size.x() <= 6.5 && size.z() <= 2.3;
      return c->object->has_category_prefix("vehicle.car") && size.x() >= 5.0 && size.z() <= 2.0;
    };
    if (std::any_of(m.begin(), m.end(), pickup_sized))
      std::erase_if(m, [&](const Candidate* c) { return !pickup_sized(c); });
    else std::erase_if(m, [](const Candidate* c) { return !c->object->has_category_prefix("vehicle.truck"); });
  }
  if (m.empty() && t.category == "vehicle.truck") widen_to({"vehicle.trailer", "vehicle.construction"});
}

// Of the matches, the kind the words say first: passenger cars for "car", tall ones for "SUV",
// and the order asked ("the last", "the car behind me": the most nearly straight behind).
void prefer_said_kind(const Selector& t, std::vector<const Candidate*>& m) {
  // "the white car", "both cars", "the cars parked on the left" mean passenger cars when any
  // match, not the white bus; a bare "all cars" clears the road of every vehicle (the dev cases'
  // reading).
  const bool qualified = t.color || t.region || t.lane || t.road_side || t.moving || t.parked || t.approaching;
  if ((t.quantity != "all" || qualified) && t.category == "vehicle" && t.noun.find("car") != std::string::npos) {
    std::vector<const Candidate*> cars;
    for (const auto* c : m)
      if (c->object->has_category_prefix("vehicle.car") || c->object->has_category_prefix("vehicle.emergency"))
        cars.push_back(c);
    if (!cars.empty()) m = cars;
    // "the broken-down car" beside a police car: one "car" is a plain one where there is one
    // ("the last parked car" counts along the row, police cars in it).
    if (t.quantity == "one" && !t.order && t.noun.find("police") == std::string::npos) {
      std::vector<const Candidate*> plain;
      for (const auto* c : m)
        if (c->object->has_category_prefix("vehicle.car")) plain.push_back(c);
      if (!plain.empty()) m = plain;
    }
  }
  // "the white SUV": of the cars that match, the tall ones. "The van": datasets label vans as
  // cars, so a car that is van-tall (not the nearest motorbike); a plain car if no car is.
  const auto types = lexicon::find_types(text::words(t.noun));
  const bool van = !types.empty() && types.front().type.type == "van";
  if (t.noun == "suv" || t.noun == "suvs" || t.noun == "jeep" || t.noun == "crossover" || van) {
    std::vector<const Candidate*> cars, tall;
    for (const auto* c : m) {
      const bool car = c->object->has_category_prefix("vehicle.car") || c->object->has_category_prefix("vehicle.emergency");
      if (!car) continue;
      cars.push_back(c);
      if (c->object->size_lwh.z() >= (van ? 1.9 : 1.65)) tall.push_back(c);
    }
    if (!tall.empty()) m = tall;
    else if (van && !cars.empty()) m = cars;
  }
  // "the taxis" where the scene labels none as such: a taxi rank's yellow cars, if there are any.
  if (!types.empty() && types.front().type.type == "taxi")
    narrow_to(m, [](const Candidate* c) {
      return c->object->color_rgb && lexicon::color_class(*c->object->color_rgb) == "yellow";
    });
  if (t.order == "queue_head" || t.order == "queue_tail") keep_queue_ends(t.order == "queue_head", m);
  if (t.order == "farthest") std::reverse(m.begin(), m.end());
  if (t.order == "slowest" || t.order == "fastest")
    std::stable_sort(m.begin(), m.end(), [&](const Candidate* a, const Candidate* b) {
      return t.order == "fastest" ? a->speed > b->speed : a->speed < b->speed;
    });
  if (t.order == "largest" || t.order == "smallest") {
    const auto volume = [](const Candidate* c) { return c->object->size_lwh.prod(); };
    std::stable_sort(m.begin(), m.end(), [&](const Candidate* a, const Candidate* b) {
      return t.order == "largest" ? volume(a) > volume(b) : volume(a) < volume(b);
    });
  }
  // "the car behind me": the one most nearly straight behind (or ahead), then the nearest.
  if (!t.order && t.quantity == "one" && (t.region == "front" || t.region == "back"))
    std::stable_sort(m.begin(), m.end(), [](const Candidate* a, const Candidate* b) {
      return std::abs(a->pe.y()) + 0.1 * a->pe.norm() < std::abs(b->pe.y()) + 0.1 * b->pe.norm();
    });
}

// "the cars waiting at the level crossing": within 25 m of where a railway crosses the road, and
// the queue behind them (each within 12 m of one kept). A map with no railway narrows nothing.
void keep_at_rail_crossing(const scene::Scene& scene, std::vector<const Candidate*>& m) {
  const auto points = language::rail_crossings(scene.lanes);
  if (points.empty()) return;
  const auto start = [](const Candidate* c) { return Eigen::Vector2d(c->object->track.front().center.head<2>()); };
  std::vector<const Candidate*> kept;
  for (const Candidate* c : m)
    if (std::any_of(points.begin(), points.end(), [&](const Eigen::Vector2d& p) { return (start(c) - p).norm() < 25; }))
      kept.push_back(c);
  for (size_t k = 0; k < kept.size(); ++k)
    for (const Candidate* c : m)
      if (std::find(kept.begin(), kept.end(), c) == kept.end() && (start(c) - start(kept[k])).norm() < 12)
        kept.push_back(c);
  std::erase_if(m, [&](const Candidate* c) { return std::find(kept.begin(), kept.end(), c) == kept.end(); });
}

// "the bike in the bus lane": on a lane of that use. A map with no such lane says nothing either
// way ("the cars waiting to turn left" on a road without turn lanes), so nothing is narrowed.
void keep_on_lanes_of_use(const Selector& t, const scene::Scene& scene, std::vector<const Candidate*>& m) {
  if (!t.lane_use) return;
  if (*t.lane_use == "rail_crossing") return keep_at_rail_crossing(scene, m);
  const auto lanes = language::lanes_for_use(scene, *t.lane_use);
  // A lane named by a word of its own ("the drop-off lane") that the map does not have selects
  // nothing, rather than everything.
  if (lanes.empty() && !language::is_known_use(*t.lane_use)) m.clear();
  if (lanes.empty()) return;
  // A car park is an area: a car on its way out, just off the aisle, is still in it.
  const bool area = *t.lane_use == "car_park";
  std::erase_if(m, [&](const Candidate* c) {
    if (std::find(lanes.begin(), lanes.end(), c->lane.own) != lanes.end()) return false;
    if (!area) return true;
    const Eigen::Vector2d p = c->object->track.front().center.head<2>();
    return std::none_of(lanes.begin(), lanes.end(), [&](int l) {
      const auto pos = scene.lanes.project(l, p);
      return pos.s > 0 && pos.s < scene.lanes.lanes()[size_t(l)].length() &&
             std::abs(pos.lateral) < scene.lanes.lanes()[size_t(l)].width / 2 + 3.0;
    });
  });
}

// "everything on the other side of the busway": past every lane of that use beside the object, on
// the side away from the ego, in each lane's own frame (a bending road reads the same). A map
// without such a lane has nothing past it.
void keep_beyond(const Selector& t, const scene::Scene& scene, std::vector<const Candidate*>& m) {
  if (!t.beyond_use || scene.frames.empty()) return;
  const auto lanes = language::lanes_for_use(scene, *t.beyond_use);
  const Eigen::Vector2d ego = scene.frames.front().ego_to_world.translation().head<2>();
  std::vector<double> ego_lateral;  // the ego's side of each lane, once
  for (const int l : lanes) ego_lateral.push_back(scene.lanes.project(l, ego).lateral);
  std::erase_if(m, [&](const Candidate* c) {
    const Eigen::Vector2d p = c->object->track.front().center.head<2>();
    int beside = 0;
    for (size_t i = 0; i < lanes.size(); ++i) {
      const auto& lane = scene.lanes.lanes()[size_t(lanes[i])];
      const auto at = scene.lanes.project(lanes[i], p);
      if (at.s <= 0 || at.s >= lane.length()) continue;
      ++beside;
      if (at.lateral * ego_lateral[i] >= 0 || std::abs(at.lateral) < lane.width / 2) return true;
    }
    return beside == 0;
  });
}

// "the cars parked past the junction": beyond (or short of) the first junction ahead of the ego.
// A map with none says nothing either way.
void keep_by_junction(const Selector& t, const scene::Scene& scene, std::vector<const Candidate*>& m) {
  if (!t.junction || scene.frames.empty()) return;
  const auto& pose = scene.frames.front().ego_to_world;
  const Eigen::Vector3d fwd = pose.linear().col(0);
  const auto span = scene.lanes.junction_ahead(pose.translation().head<2>(), std::atan2(fwd.y(), fwd.x()));
  if (!span) return;
  const bool after = *t.junction == "after";
  std::erase_if(m, [&](const Candidate* c) { return after ? c->pe.x() < span->to + 2 : c->pe.x() > span->from - 2; });
}

// Whether the object moves at least 0.8 m against its heading within two seconds somewhere in the
// clip (more than a label's jitter, less than backing out of a bay).
bool reverses(const scene::ObjectTrack& o, double frame_rate_hz) {
  const int window = std::max(1, int(std::lround(2 * frame_rate_hz)));
  const auto& t = o.track;
  for (size_t i = 0, j = 0; i < t.size(); ++i) {
    while (j < t.size() && t[j].frame < t[i].frame + window) ++j;
    if (j == t.size()) break;
    const Eigen::Vector2d d = (t[j].center - t[i].center).head<2>();
    if (std::cos(t[i].yaw) * d.x() + std::sin(t[i].yaw) * d.y() < -0.8) return true;
  }
  return false;
}

// The object as the user sees it: at frame 0 when it is there, else where it comes into view
// (a real recording labels a car only once a sensor sees it), placed relative to the ego then,
// as the video shows it. Speed over the part of the clip it is seen in.
// `from_start`: world to the ego at frame 0; `reversing`: whether any selector asks (a pass over the
// whole track, per object, per selection).
std::optional<Candidate> candidate_of(const scene::Scene& scene, const scene::ObjectTrack& o,
                                      const Eigen::Isometry3d& from_start, bool reversing) {
  if (o.track.empty() || scene.frames.empty()) return std::nullopt;
  const int first = std::max(0, o.track.front().frame);
  if (size_t(first) >= scene.frames.size()) return std::nullopt;
  const auto p0 = o.at(first);
  if (!p0) return std::nullopt;
  const Eigen::Isometry3d to_ego = scene.frames[size_t(first)].ego_to_world.inverse();
  double speed = 0;
  const int last = o.track.back().frame;
  if (last > first && scene.frames.size() > size_t(last)) {
    const double dt = scene.frames[size_t(last)].timestamp_s - scene.frames[size_t(first)].timestamp_s;
    if (dt > 0) speed = (o.track.back().center - p0->center).head<2>().norm() / dt;
  }
  const double ego_turn = std::atan2(to_ego.linear()(1, 0), to_ego.linear()(0, 0));
  const double d0 = (from_start * p0->center).head<2>().norm();
  return Candidate{&o, (to_ego * p0->center).head<2>(), speed, lane_relation(scene, p0->center.head<2>()),
                   p0->yaw + ego_turn, reversing && reverses(o, scene.frame_rate_hz), d0};
}

}  // namespace

Selection select_objects(const scene::Scene& scene, const DeletionRequest& r, const std::vector<std::string>& removed,
                         const std::vector<std::string>& it) {
  Selection out;
  if (r.unsupported) {
    out.problems.push_back("there is no " + *r.unsupported + " in the scene, and it is not something that can be selected");
    return out;
  }
  std::vector<Candidate> cands;
  const auto asks_reversing = [](const std::vector<Selector>& v) {
    return std::any_of(v.begin(), v.end(), [](const Selector& s) { return s.reversing; });
  };
  const bool reversing = asks_reversing(r.targets) || asks_reversing(r.except);
  const Eigen::Isometry3d from_start =
      scene.frames.empty() ? Eigen::Isometry3d::Identity() : scene.frames.front().ego_to_world.inverse();
  for (const auto& o : scene.objects)
    if (std::find(removed.begin(), removed.end(), o.id) == removed.end())
      if (auto c = candidate_of(scene, o, from_start, reversing)) cands.push_back(*c);
  std::sort(cands.begin(), cands.end(), [](const Candidate& a, const Candidate& b) { return a.d0 < b.d0; });
  std::vector<std::string> chosen;
  // What "it" was in an earlier round: the first phrase's relation places by it.
  std::vector<Candidate> earlier;
  for (const auto& o : scene.objects)
    if (std::find(it.begin(), it.end(), o.id) != it.end())
      if (auto c = candidate_of(scene, o, from_start, reversing)) earlier.push_back(*c);
  const Candidate* last = earlier.empty() ? nullptr : &earlier.front();  // what the phrase before chose ("... and the truck behind it")
  // "the car queuing behind the truck": of the trucks, the one with such a car behind it (nearest
  // first); the anchor phrase's matches wait for the phrase placed by them.
  std::vector<const Candidate*> anchors;
  for (const auto& said : r.targets) {
    Selector t = said;
    if (t.lane == "main") t.lane = main_road(scene);
    std::vector<const Candidate*> m;
    for (const auto& c : cands)
      if (matches(t, c)) m.push_back(&c);
    // "the bus at the bus stop" where the stop is part of a driving lane: a map with no parking
    // lane says nothing about the place either way.
    if (m.empty() && t.lane == "parking" && !scene_has_parking(scene)) {
      Selector anywhere = t;
      anywhere.lane.reset();
      for (const auto& c : cands)
        if (matches(anywhere, c)) m.push_back(&c);
    }
    keep_on_lanes_of_use(t, scene, m);
    keep_by_junction(t, scene, m);
    keep_beyond(t, scene, m);
    if (t.of_previous && !anchors.empty()) {
      // The first anchor with one right there (in its lane, within 30 m), else the first with any.
      const auto all = m;
      std::optional<std::vector<const Candidate*>> loose;
      m.clear();
      for (const auto* a : anchors) {
        auto placed = placed_by(all, *a, *t.of_previous);
        if (!placed.empty() && right_there(*a, *placed.front())) {
          m = std::move(placed);
          break;
        }
        if (!placed.empty() && !loose) loose = std::move(placed);
      }
      if (m.empty() && loose) m = std::move(*loose);
    } else if (t.of_previous && last != nullptr) {
      m = placed_by(m, *last, *t.of_previous);
    } else if (t.of_previous) {  // "it" names nothing: behind or ahead of the ego, as the words say
      Selector by_ego = t;
      by_ego.of_previous.reset();
      if (*t.of_previous == "behind" || *t.of_previous == "front") by_ego.region = *t.of_previous == "behind" ? "back" : "front";
      std::erase_if(m, [&](const Candidate* c) { return !matches(by_ego, *c); });
    }
    anchors.clear();
    widen_or_narrow(t, scene, cands, m);
    if (m.empty()) {
      out.problems.push_back("no " + describe(t).substr(t.quantity == "all" ? 6 : 4) + " in the scene" +
                             (removed.empty() ? "" : " (or it was already removed)"));
      continue;
    }
    prefer_said_kind(t, m);
    last = m.front();
    if (t.anchor_only) {
      anchors = m;
      continue;
    }
    if (t.quantity == "all") {
      for (const auto* c : m) chosen.push_back(c->object->id);
    } else if (t.quantity == "n") {
      for (size_t i = 0; i < m.size() && int(i) < t.n; ++i) chosen.push_back(m[i]->object->id);
      if (int(m.size()) < t.n)
        out.problems.push_back("asked for " + std::to_string(t.n) + " but the scene has only " + std::to_string(m.size()));
    } else {
      const size_t k = size_t(std::max(1, t.nth)) - 1;
      if (k >= m.size()) {
        out.problems.push_back("there is no " + describe(t).substr(4) + ": only " + std::to_string(m.size()) + " match");
        continue;
      }
      chosen.push_back(m[k]->object->id);
      last = m[k];
    }
  }
  for (const auto& said : r.except) {
    Selector e = said;
    if (e.lane == "main") e.lane = main_road(scene);
    // What an exception names is read as a selection is ("the taxis": the yellow cars, "the vans":
    // the tall ones), all of it.
    std::vector<const Candidate*> m;
    for (const auto& c : cands)
      if (matches(e, c)) m.push_back(&c);
    prefer_said_kind(e, m);
    for (const auto* c : m) chosen.erase(std::remove(chosen.begin(), chosen.end(), c->object->id), chosen.end());
  }
  for (const auto& c : cands)
    if (std::find(chosen.begin(), chosen.end(), c.object->id) != chosen.end() &&
        std::find(out.ids.begin(), out.ids.end(), c.object->id) == out.ids.end())
      out.ids.push_back(c.object->id);
  return out;
}

}  // namespace chatsim::agents::deletion
