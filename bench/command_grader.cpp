#include "bench/command_grader.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "agents/language/lexicon.hpp"
#include "agents/motion/planner.hpp"

namespace chatsim::bench {
namespace {

using nlohmann::json;
constexpr double kDeg = 180 / std::numbers::pi;

struct Ego0 {
  Eigen::Isometry3d to_ego;
  Eigen::Vector2d world_pos;
};

Eigen::Vector2d to_ego(const scene::Scene& s, double x, double y) {
  return (s.world_to_ego0() * Eigen::Vector3d(x, y, 0)).head<2>();
}

double angle_deg(const Eigen::Vector2d& p) { return std::atan2(p.y(), p.x()) * kDeg; }

bool in_region(const std::string& r, const Eigen::Vector2d& p) {
  const double a = angle_deg(p);
  if (r == "front") return std::abs(a) <= 25;
  if (r == "left_front") return a >= 10 && a <= 75;
  if (r == "right_front") return a >= -75 && a <= -10;
  if (r == "left") return a >= 60 && a <= 120;
  if (r == "right") return a >= -120 && a <= -60;
  if (r == "back") return std::abs(a) >= 110;
  return false;
}

double wrap(double a) { return std::remainder(a, 2 * std::numbers::pi); }

struct Track {
  std::vector<Eigen::Vector2d> p;   // world
  std::vector<double> yaw, t;
};

Track track_of(const json& v) {
  Track tr;
  for (const auto& q : v.at("trajectory")) {
    tr.p.emplace_back(q.at("x").get<double>(), q.at("y").get<double>());
    tr.yaw.push_back(q.at("yaw").get<double>());
    tr.t.push_back(q.at("t_s").get<double>());
  }
  return tr;
}

double mean_speed(const Track& t) {
  if (t.p.size() < 2 || t.t.back() <= t.t.front()) return 0;
  double d = 0;
  for (size_t i = 1; i < t.p.size(); ++i) d += (t.p[i] - t.p[i - 1]).norm();
  return d / (t.t.back() - t.t.front());
}

double max_speed(const Track& t) {
  double m = 0;
  for (size_t i = 1; i < t.p.size(); ++i)
    if (t.t[i] > t.t[i - 1]) m = std::max(m, (t.p[i] - t.p[i - 1]).norm() / (t.t[i] - t.t[i - 1]));
  return m;
}

// Displacement over the first second.
Eigen::Vector2d first_second(const Track& t) {
  size_t k = 0;
  while (k + 1 < t.p.size() && t.t[k] - t.t[0] < 1.0) ++k;
  return t.p[k] - t.p[0];
}

double heading_change(const Track& t) {
  double total = 0;
  for (size_t i = 1; i < t.yaw.size(); ++i) total += wrap(t.yaw[i] - t.yaw[i - 1]);
  return total * kDeg;
}

double final_lateral(const Track& t) {
  const Eigen::Vector2d d = t.p.back() - t.p.front();
  return -std::sin(t.yaw[0]) * d.x() + std::cos(t.yaw[0]) * d.y();
}

double max_abs_lateral(const Track& t) {
  double m = 0;
  for (const auto& p : t.p) {
    const Eigen::Vector2d d = p - t.p.front();
    m = std::max(m, std::abs(-std::sin(t.yaw[0]) * d.x() + std::cos(t.yaw[0]) * d.y()));
  }
  return m;
}

std::string action_of(const Track& t) {
  if (max_speed(t) < 0.5) return "static";
  const Eigen::Vector2d d = t.p.back() - t.p.front();
  const Eigen::Vector2d h(std::cos(t.yaw[0]), std::sin(t.yaw[0]));
  if (d.dot(h) < 0) return "backward";
  const double turn = heading_change(t);
  if (turn > 45) return "turn_left";
  if (turn < -45) return "turn_right";
  const double lat = final_lateral(t);
  if (std::abs(turn) < 20 && std::abs(lat) >= 2 && std::abs(lat) <= 5) return lat > 0 ? "lane_change_left" : "lane_change_right";
  if (std::abs(turn) < 20 && max_abs_lateral(t) < 1.5) return "straight";
  return "other";
}

// Whether a track keeps to the one driving lane it starts on, its way, to the end: on a road that
// bends (a real recording's, a drive-thru's loop) that is driving straight on.
bool keeps_to_its_lane(const scene::Scene& s, const Track& t) {
  const auto& map = s.lanes;
  for (const auto& pos : map.containing(t.p.front(), 0.5)) {
    const auto& lane = map.lanes()[size_t(pos.lane)];
    if (lane.type != "driving" || std::cos(map.travel_yaw_at(pos.lane, pos.s) - t.yaw.front()) < 0.7) continue;
    const bool stays = std::all_of(t.p.begin(), t.p.end(), [&](const Eigen::Vector2d& p) {
      const auto on = map.project(pos.lane, p);
      return std::abs(on.lateral) <= lane.width / 2 + 0.5 && on.s >= -1 && on.s <= lane.length() + 1;
    });
    if (stays) return true;
  }
  return false;
}

bool action_is(const scene::Scene& s, const Track& t, const std::string& a) {
  if (a == "static") return max_speed(t) < 0.5;
  if (a == "backward") {
    const Eigen::Vector2d d = t.p.back() - t.p.front();
    return d.dot(Eigen::Vector2d(std::cos(t.yaw[0]), std::sin(t.yaw[0]))) < 0;
  }
  const double turn = heading_change(t);
  if (a == "turn_left") return turn > 45;
  if (a == "turn_right") return turn < -45;
  if (a == "straight") return (std::abs(turn) < 20 && max_abs_lateral(t) < 1.5) || keeps_to_its_lane(s, t);
  if (a == "lane_change_left" || a == "lane_change_right") {
    const double lat = final_lateral(t);
    const double yaw_end = wrap(t.yaw.back() - t.yaw.front()) * kDeg;
    const bool side = a == "lane_change_left" ? lat > 0 : lat < 0;
    return side && std::abs(lat) >= 2 && std::abs(lat) <= 5 && std::abs(yaw_end) <= 20;
  }
  return false;
}

bool speed_is(const Track& t, const std::string& s) {
  const double m = mean_speed(t);
  if (s == "static") return max_speed(t) < 0.5;
  if (s == "slow") return m >= 0.5 && m <= 6;
  if (s == "normal") return m >= 6 && m <= 12;
  if (s == "fast") return m > 10;
  return false;
}

bool on_lane(const scene::Scene& s, const Track& t) {
  for (const auto& p : t.p) {
    bool ok = false;
    for (size_t i = 0; i < s.lanes.lanes().size() && !ok; ++i) {
      const auto& l = s.lanes.lanes()[i];
      if (l.type != "driving" && l.type != "parking") continue;
      const auto pos = s.lanes.project(int(i), p);
      ok = (s.lanes.point_at(int(i), pos.s) - p).norm() <= l.width / 2 + 0.5;
    }
    if (!ok) return false;
  }
  return true;
}

bool wrong_way(const scene::Scene& s, const Track& t) {
  const Eigen::Vector2d d = first_second(t);
  if (d.norm() < 1e-3) return false;
  const auto on = s.lanes.containing(t.p.front(), 0.5);
  if (on.empty()) return false;
  const auto& l = s.lanes.lanes()[size_t(on.front().lane)];
  if (l.direction == scene::TrafficDirection::Both) return false;
  const double yaw = s.lanes.travel_yaw_at(on.front().lane, on.front().s);
  return d.dot(Eigen::Vector2d(std::cos(yaw), std::sin(yaw))) < 0;
}

std::string type_of(const json& v) {
  if (v.contains("type")) return v["type"].get<std::string>();
  return v.value("asset", "");
}

bool type_is(const json& v, const std::string& type) {
  if (type_of(v) == type) return true;
  const std::string asset = v.value("asset", "");
  if (type == "car" && type_of(v) == "car") return true;
  return asset.find(type) != std::string::npos;
}

bool brand_is(const json& v, const std::string& brand) {
  if (v.value("asset", "").find(brand) != std::string::npos) return true;
  for (const auto& b : v.value("brand_words", std::vector<std::string>{}))
    if (b == brand) return true;
  return false;
}

std::vector<std::string> select(const scene::Scene& s, const json& sel) {
  if (sel.contains("ids")) return sel["ids"].get<std::vector<std::string>>();
  struct C {
    std::string id;
    double dist;
  };
  std::vector<C> out;
  for (const auto& o : s.objects) {
    const auto p0 = o.at(0);
    if (!p0) continue;
    if (sel.contains("category") && !o.has_category_prefix(sel["category"].get<std::string>())) continue;
    if (sel.contains("color")) {
      std::string want = sel["color"];
      if (want == "grey" || want == "silver") want = "gray";
      if (!o.color_rgb || agents::lexicon::color_class(*o.color_rgb) != want) continue;
    }
    const Eigen::Vector2d pe = to_ego(s, p0->center.x(), p0->center.y());
    if (sel.contains("region") && !in_region(sel["region"], pe)) continue;
    if (sel.contains("moving")) {
      double speed = 0;
      const int last = o.track.back().frame;
      const double dt = s.frames[size_t(last)].timestamp_s - s.frames[0].timestamp_s;
      if (dt > 0) speed = (o.track.back().center - p0->center).head<2>().norm() / dt;
      if ((speed > 0.5) != sel["moving"].get<bool>()) continue;
    }
    out.push_back({o.id, pe.norm()});
  }
  std::sort(out.begin(), out.end(), [](const C& a, const C& b) { return a.dist < b.dist; });
  if (sel.value("nearest", false) && !out.empty()) out.resize(1);
  if (sel.value("farthest", false) && !out.empty()) out = {out.back()};
  std::vector<std::string> ids;
  for (const auto& c : out) ids.push_back(c.id);
  return ids;
}

std::string check_added(const scene::Scene& s, const json& added, const json& c) {
  const size_t i = c.at("index").get<size_t>();
  if (i >= added.size()) return "no added vehicle " + std::to_string(i);
  const json& v = added[i];
  const Track t = track_of(v);
  if (t.p.empty()) return "empty trajectory";
  const Eigen::Vector2d start = to_ego(s, t.p[0].x(), t.p[0].y());
  if (c.contains("type") && !type_is(v, c["type"])) return "type " + type_of(v);
  if (c.contains("brand") && !brand_is(v, c["brand"])) return "asset " + v.value("asset", "");
  if (c.contains("color")) {
    std::string want = c["color"];
    if (want == "grey" || want == "silver") want = "gray";
    const auto rgb = v.at("color_rgb").get<std::array<int, 3>>();
    if (agents::lexicon::color_class(rgb) != want) return "colour " + agents::lexicon::color_class(rgb);
  }
  if (c.contains("region") && !in_region(c["region"], start))
    return "start angle " + std::to_string(angle_deg(start));
  if (c.contains("distance")) {
    const double d = start.norm();
    if (d < c["distance"][0].get<double>() || d > c["distance"][1].get<double>()) return "distance " + std::to_string(d);
  }
  if (c.contains("relative_to")) {
    const size_t j = c["relative_to"].at("index").get<size_t>();
    if (j >= added.size()) return "no added vehicle " + std::to_string(j);
    const Track tj = track_of(added[j]);
    const Eigen::Vector2d d = t.p[0] - tj.p[0];
    const double yaw = tj.yaw[0];
    const Eigen::Vector2d local(std::cos(yaw) * d.x() + std::sin(yaw) * d.y(), -std::sin(yaw) * d.x() + std::cos(yaw) * d.y());
    if (!in_region(c["relative_to"].at("region"), local)) return "relative angle " + std::to_string(angle_deg(local));
  }
  if (c.contains("heading")) {
    const Eigen::Vector2d ego = (s.frames[0].ego_to_world.translation()).head<2>();
    const bool toward = first_second(t).dot(ego - t.p[0]) > 0;
    if ((c["heading"] == "toward") != toward) return toward ? "heading toward" : "heading away";
  }
  if (c.contains("speed") && !speed_is(t, c["speed"])) return "mean speed " + std::to_string(mean_speed(t));
  if (c.contains("speed_kmh")) {
    const double kmh = mean_speed(t) * 3.6;
    if (kmh < c["speed_kmh"][0].get<double>() || kmh > c["speed_kmh"][1].get<double>()) return "km/h " + std::to_string(kmh);
  }
  if (c.contains("action") && !action_is(s, t, c["action"])) return "action looks like " + action_of(t);
  if (c.contains("wrong_way") && wrong_way(s, t) != c["wrong_way"].get<bool>()) return "wrong_way mismatch";
  if (c.contains("on_lane") && c["on_lane"].get<bool>() && !on_lane(s, t)) return "leaves the lanes";
  return "";
}

// Every vehicle of the edited scene: labelled ones not removed, then the added ones in order.
std::vector<agents::motion::Obstacle> vehicles_of(const scene::Scene& s, const json& state, size_t* first_added) {
  std::vector<agents::motion::Obstacle> all;
  const auto removed = state.value("removed", std::vector<std::string>{});
  for (auto& ob : agents::motion::scene_obstacles(s, removed)) {
    const auto* o = s.object(ob.id);
    if (o != nullptr && o->has_category_prefix("vehicle")) all.push_back(std::move(ob));
  }
  *first_added = all.size();
  for (const auto& v : state.value("added", json::array())) {
    const Track t = track_of(v);
    std::vector<agents::motion::Pose2> poses;
    for (size_t i = 0; i < t.p.size(); ++i) poses.push_back({t.p[i].x(), t.p[i].y(), t.yaw[i]});
    const auto sz = v.at("size_lwh").get<std::array<double, 3>>();
    all.push_back(agents::motion::trajectory_obstacle(v.value("id", "added"), {sz[0], sz[1], sz[2]}, poses));
  }
  return all;
}

// Whom a meets first (boxes shrunk by 10 %), as "<a> meets <b> at frame f", or "".
std::string first_meeting(const std::vector<agents::motion::Obstacle>& all, size_t a, size_t others_from) {
  for (size_t b = others_from; b < all.size(); ++b) {
    if (b == a) continue;
    for (size_t f = 0; f < std::min(all[a].poses.size(), all[b].poses.size()); ++f) {
      if (!all[a].poses[f] || !all[b].poses[f]) continue;
      if (agents::motion::boxes_overlap(*all[a].poses[f], all[a].size_lwh, *all[b].poses[f], all[b].size_lwh, 0.9))
        return all[a].id + " meets " + all[b].id + " at frame " + std::to_string(f);
    }
  }
  return "";
}

std::string check_no_collision(const scene::Scene& s, const json& state) {
  size_t first_added = 0;
  const auto all = vehicles_of(s, state, &first_added);
  for (size_t a = 0; a < all.size(); ++a)
    if (auto why = first_meeting(all, a, a + 1); !why.empty()) return why;
  return "";
}

}  // namespace

std::vector<CheckResult> grade_case(const scene::Scene& s, const json& state, const json& expect) {
  std::vector<CheckResult> out;
  const auto removed = state.value("removed", std::vector<std::string>{});
  const json added = state.value("added", json::array());
  for (const auto& c : expect) {
    CheckResult r;
    r.check = c.dump();
    const std::string kind = c.value("check", "");
    std::string why;
    if (kind == "removed") {
      const auto want = select(s, c.at("select"));
      if (c.value("exactly", true)) {
        auto a = removed, b = want;
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        if (a != b) why = "removed " + json(removed).dump() + ", expected " + json(want).dump();
      } else {
        for (const auto& id : want)
          if (std::find(removed.begin(), removed.end(), id) == removed.end()) why = id + " not removed";
      }
    } else if (kind == "removed_count") {
      if (int(removed.size()) != c.at("n").get<int>()) why = "removed " + std::to_string(removed.size());
    } else if (kind == "kept") {
      for (const auto& id : select(s, c.at("select")))
        if (std::find(removed.begin(), removed.end(), id) != removed.end()) why = id + " was removed";
    } else if (kind == "added_count") {
      const int n = int(added.size());
      if ((c.contains("n") && n != c["n"].get<int>()) || (c.contains("min") && n < c["min"].get<int>()) ||
          (c.contains("max") && n > c["max"].get<int>()))
        why = "added " + std::to_string(n);
    } else if (kind == "added") {
      why = check_added(s, added, c);
    } else if (kind == "view") {
      const json v = state.value("view", json::object());
      if (c.contains("translation_m")) {
        const double tol = c.value("tol_m", 0.25);
        const auto t = v.value("translation_m", std::array<double, 3>{0, 0, 0});
        for (size_t i = 0; i < 3; ++i)
          if (std::abs(t[i] - c["translation_m"][i].get<double>()) > tol) why = "translation " + json(t).dump();
      }
      if (c.contains("yaw_deg") && std::abs(v.value("yaw_deg", 0.0) - c["yaw_deg"].get<double>()) > c.value("tol_deg", 3.0))
        why = "yaw " + std::to_string(v.value("yaw_deg", 0.0));
    } else if (kind == "ego_motion") {
      const std::string got = state.value("view", json::object()).value("ego_motion", "none");
      if (got != c.at("value").get<std::string>()) why = "ego_motion " + got;
    } else if (kind == "no_collision") {
      why = check_no_collision(s, state);
    } else if (kind == "refused") {
      if (state.value("unresolved", json::array()).empty()) why = "nothing unresolved";
    } else {
      why = "unknown check '" + kind + "'";
    }
    r.pass = why.empty();
    r.detail = why;
    out.push_back(r);
  }
  return out;
}

MotionQuality motion_quality(const scene::Scene& s, const json& state) {
  MotionQuality q;
  size_t first_added = 0;
  const auto all = vehicles_of(s, state, &first_added);
  for (size_t a = first_added; a < all.size(); ++a) q.no_overlap += first_meeting(all, a, 0).empty() ? 1 : 0;
  const auto ego = agents::motion::ego_obstacle(s);
  for (size_t a = first_added; a < all.size(); ++a)
    q.clear_of_ego += first_meeting({all[a], ego}, 0, 1).empty() ? 1 : 0;
  for (const auto& v : state.value("added", json::array())) {
    const Track t = track_of(v);
    if (t.p.empty()) continue;
    ++q.vehicles;
    q.on_lane += on_lane(s, t) ? 1 : 0;
    const json intent = v.value("intent", json::object());
    q.action_match += action_is(s, t, intent.value("action", "straight")) ? 1 : 0;
    const std::string speed = intent.value("speed", "normal");
    bool ok = speed_is(t, speed);
    if (intent.contains("speed_mps") && speed != "static") ok = std::abs(mean_speed(t) - intent["speed_mps"].get<double>()) < 0.25 * intent["speed_mps"].get<double>() + 0.5;
    q.speed_match += ok ? 1 : 0;
  }
  return q;
}

}  // namespace chatsim::bench
