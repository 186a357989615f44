#include "agents/motion/planner_impl.hpp"

#include <cmath>

// Placements relative to a vehicle that are not simply ahead of or behind it on its lane.
namespace chatsim::agents::motion::detail {

double Planner::anchor_base_gap() const { return (req_.anchor->size_lwh.x() + req_.size_lwh.x()) / 2 + 2.0; }

std::vector<std::pair<double, double>> Planner::gaps_from_anchor(double base_gap, double headway) const {
  std::vector<std::pair<double, double>> out;
  if (m_.distance_m) {
    // A distance said holds as one from the ego does (within max(3 m, 20 %)): a speed said too
    // ("doing 40 km/h 10 m behind the black car") makes it follow, not start further back. Outside
    // that, only when nothing inside is free.
    const double want = std::max(*m_.distance_m, base_gap), tol = distance_tolerance(want);
    for (double gap = base_gap; gap < want + 45; gap += 0.5)
      out.push_back({gap, std::abs(gap - want) + (std::abs(gap - want) > tol ? kDistanceMissedPenalty : 0.0)});
    return out;
  }
  for (double gap = base_gap + headway; gap < base_gap + headway + 45; gap += 0.5)
    out.push_back({gap, gap - base_gap - headway});
  return out;
}

// "Past the cone", "parked after the green car": along the anchor's lane away from the ego,
// whichever way the anchor faces; where its lane (a parking lane) has no room there, the driving
// lane beside it (within 5 m), at a small cost.
void Planner::beyond_candidates(int lane, double s0, int dir, std::vector<Candidate>& out) const {
  const Anchor& a = *req_.anchor;
  const Eigen::Vector2d ap(a.start.x, a.start.y);
  const double base_gap = anchor_base_gap();
  const double headway = a.speed_mps > 0.5 ? std::min(a.speed_mps * 1.0, 20.0) : 0.0;
  const auto along = [&](int li, double s_at, int d, double extra) {
    const auto& l = scene_.lanes.lanes()[size_t(li)];
    const int k = (scene_.lanes.point_at(li, s_at + d * 5.0) - ego_.p).norm() >= (ap - ego_.p).norm() ? 1 : -1;
    const bool parked = wants_parked(l.for_stopping()) || (a.speed_mps == 0 && nothing_said_about_motion());
    size_t n = 0;
    for (const auto& [gap, cost] : gaps_from_anchor(base_gap, headway)) {
      const double s = s_at + k * d * gap;
      if (s < 0 || s > l.length()) continue;
      out.push_back({li, s, d, parked, cost + extra});
      ++n;
    }
    return n;
  };
  if (along(lane, s0, dir, 0) > 0 || !scene_.lanes.lanes()[size_t(lane)].for_stopping()) return;
  for (size_t li = 0; li < scene_.lanes.lanes().size(); ++li) {
    const auto& l = scene_.lanes.lanes()[li];
    const auto pos = scene_.lanes.project(int(li), ap);
    if (l.type != "driving" || std::abs(pos.lateral) > 5 || (scene_.lanes.point_at(int(li), pos.s) - ap).norm() > 5) continue;
    along(int(li), pos.s, legal_dir(l), 3.0);
  }
}

// "Opposite the school bus": level with the anchor across the road (on the ego's other side of
// it, at least 4 m across), a kerb or parking lane before a lane of traffic.
void Planner::opposite_candidates(std::vector<Candidate>& out) const {
  const Anchor& a = *req_.anchor;
  const Eigen::Vector2d ap(a.start.x, a.start.y);
  const double anchor_y = ego_.to_ego(ap).y();
  const double across = anchor_y >= 0 ? -1 : 1;
  for (size_t li = 0; li < scene_.lanes.lanes().size(); ++li) {
    const auto& l = scene_.lanes.lanes()[li];
    if (l.type != "driving" && !l.for_stopping()) continue;
    const auto pos = scene_.lanes.project(int(li), ap);
    const Eigen::Vector2d q = scene_.lanes.point_at(int(li), pos.s);
    if (across * (ego_.to_ego(q).y() - anchor_y) < 4 || (q - ap).norm() > 25) continue;
    const bool parked = wants_parked(l.for_stopping()) || (a.speed_mps < 0.5 && nothing_said_about_motion());
    const double base = (q - ap).norm() + (l.for_stopping() ? 0.0 : 3.0);
    for (double shift = 0; shift < 12; shift += 0.5)
      for (int sgn : {1, -1}) {
        const double s = pos.s + sgn * shift;
        if (s >= 0 && s <= l.length()) out.push_back({int(li), s, legal_dir(l), parked, base + shift});
        if (shift == 0) break;
      }
  }
}

// Beside an anchor standing across its lane (a bay of a row of perpendicular parking): along the
// row, on its `side` (+1 its left) first, then on the other ("next to the motorbike" says no side).
void Planner::beside_in_row(int lane, double s0, int dir, int side, std::vector<Candidate>& out) const {
  const Anchor& a = *req_.anchor;
  const double tangent = scene_.lanes.tangent_yaw_at(lane, s0);
  const double left_along = -std::sin(a.start.yaw) * std::cos(tangent) + std::cos(a.start.yaw) * std::sin(tangent);
  const double gap = (a.size_lwh.y() + req_.size_lwh.y()) / 2 + 0.8;
  const bool parked = wants_parked(scene_.lanes.lanes()[size_t(lane)].for_stopping()) ||
                      (a.speed_mps < 0.5 && nothing_said_about_motion());
  for (int pass = 0; pass < 2; ++pass) {
    const double k = (pass == 0 ? side : -side) * (left_along >= 0 ? 1 : -1);
    for (double extra = 0; extra < 15; extra += 0.5) {
      const double s = s0 + k * (gap + extra);
      if (s >= 0 && s <= scene_.lanes.lanes()[size_t(lane)].length())
        out.push_back({lane, s, dir, parked, extra + 5.0 * pass});
    }
  }
}

}  // namespace chatsim::agents::motion::detail
