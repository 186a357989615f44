#include "common/scene/lane_map.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>

namespace chatsim::scene {
namespace {

Eigen::Vector2d xy(const Eigen::Vector3d& v) { return v.head<2>(); }

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

LaneMap::LaneMap(std::vector<Lane> lanes) : lanes_(std::move(lanes)) {
  for (auto& lane : lanes_) {
    lane.s.assign(lane.centerline.size(), 0.0);
    for (size_t i = 1; i < lane.centerline.size(); ++i)
      lane.s[i] = lane.s[i - 1] + (xy(lane.centerline[i]) - xy(lane.centerline[i - 1])).norm();
    Eigen::AlignedBox2d box;
    for (const auto& c : lane.centerline) box.extend(xy(c));
    if (!box.isEmpty()) box.min().array() -= lane.width / 2, box.max().array() += lane.width / 2;
    bounds_.push_back(box);
    std::vector<Eigen::AlignedBox2d> chunks;
    for (size_t first = 0; first + 1 < lane.centerline.size(); first += kSegmentsPerChunk) {
      Eigen::AlignedBox2d chunk;
      for (size_t i = first; i <= std::min(first + kSegmentsPerChunk, lane.centerline.size() - 1); ++i) chunk.extend(xy(lane.centerline[i]));
      chunks.push_back(chunk);
    }
    chunk_bounds_.push_back(std::move(chunks));
  }
}

int LaneMap::find(const std::string& id) const {
  for (size_t i = 0; i < lanes_.size(); ++i)
    if (lanes_[i].id == id) return int(i);
  return -1;
}

LanePosition LaneMap::project(int index, const Eigen::Vector2d& p) const {
  const Lane& lane = lanes_.at(size_t(index));
  const auto& chunks = chunk_bounds_[size_t(index)];
  LanePosition best{index, 0, 0, 0};
  double best_d2 = std::numeric_limits<double>::infinity();
  size_t best_i = 0;
  auto try_chunk = [&](size_t c) {
    const size_t end = std::min((c + 1) * kSegmentsPerChunk, lane.centerline.size() - 1);
    for (size_t i = c * kSegmentsPerChunk; i < end; ++i) {
      const Eigen::Vector2d a = xy(lane.centerline[i]);
      const Eigen::Vector2d d = xy(lane.centerline[i + 1]) - a;
      const double len2 = d.squaredNorm();
      if (len2 <= 0) continue;
      const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
      const Eigen::Vector2d q = a + t * d;
      const double d2 = (p - q).squaredNorm();
      // Ties go to the earlier segment (at a shared corner both are as close), whatever the
      // order the chunks are visited in.
      if (d2 < best_d2 || (d2 == best_d2 && i < best_i)) {
        best_d2 = d2;
        best_i = i;
        best.s = lane.s[i] + t * std::sqrt(len2);
        best.lateral = cross2(d, p - a) / std::sqrt(len2);
        best.tangent_yaw = std::atan2(d.y(), d.x());
      }
    }
  };
  if (chunks.empty()) return best;  // fewer than two centreline points
  // The nearest chunk first, then only the chunks whose bounds could hold a segment as close:
  // a long centreline is mostly far from p.
  size_t nearest = 0;
  double nearest_d2 = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < chunks.size(); ++c)
    if (const double d2 = chunks[c].squaredExteriorDistance(p); d2 < nearest_d2) nearest_d2 = d2, nearest = c;
  try_chunk(nearest);
  for (size_t c = 0; c < chunks.size(); ++c)
    if (c != nearest && chunks[c].squaredExteriorDistance(p) <= best_d2) try_chunk(c);
  return best;
}

std::optional<LanePosition> LaneMap::nearest(const Eigen::Vector2d& p, const std::string& type) const {
  std::optional<LanePosition> best;
  for (size_t i = 0; i < lanes_.size(); ++i) {
    if (!type.empty() && lanes_[i].type != type) continue;
    if (lanes_[i].centerline.size() < 2) continue;
    const auto pos = project(int(i), p);
    if (!best || std::abs(pos.lateral) < std::abs(best->lateral)) best = pos;
  }
  return best;
}

std::optional<LanePosition> LaneMap::within(size_t i, const Eigen::Vector2d& p, double margin) const {
  if (lanes_[i].centerline.size() < 2) return std::nullopt;
  // Far from the lane's extent: not on it (the planner asks this for every pose it tries).
  if (bounds_[i].exteriorDistance(p) > margin) return std::nullopt;
  const auto pos = project(int(i), p);
  const bool inside_extent = pos.s > 1e-6 && pos.s < lanes_[i].length() - 1e-6;
  if (inside_extent && std::abs(pos.lateral) <= lanes_[i].width / 2 + margin) return pos;
  return std::nullopt;
}

bool LaneMap::on_some_lane(const Eigen::Vector2d& p, double margin, int& hint) const {
  if (hint >= 0 && size_t(hint) < lanes_.size() && within(size_t(hint), p, margin)) return true;
  for (size_t i = 0; i < lanes_.size(); ++i)
    if (int(i) != hint && within(i, p, margin)) {
      hint = int(i);
      return true;
    }
  return false;
}

std::vector<LanePosition> LaneMap::containing(const Eigen::Vector2d& p, double margin) const {
  std::vector<LanePosition> out;
  for (size_t i = 0; i < lanes_.size(); ++i)
    if (const auto pos = within(i, p, margin)) out.push_back(*pos);
  std::sort(out.begin(), out.end(),
            [](const LanePosition& a, const LanePosition& b) { return std::abs(a.lateral) < std::abs(b.lateral); });
  return out;
}

std::vector<int> LaneMap::in_region(const Eigen::Vector2d& p, double radius) const {
  std::vector<int> out;
  for (size_t i = 0; i < lanes_.size(); ++i)
    if (lanes_[i].centerline.size() >= 2 && std::abs(project(int(i), p).lateral) <= radius &&
        (point_at(int(i), project(int(i), p).s) - p).norm() <= radius)
      out.push_back(int(i));
  return out;
}

Eigen::Vector2d LaneMap::point_at(int index, double s) const {
  const Lane& lane = lanes_.at(size_t(index));
  if (lane.centerline.size() < 2) return lane.centerline.empty() ? Eigen::Vector2d::Zero() : xy(lane.centerline[0]);
  s = std::clamp(s, 0.0, lane.length());
  auto it = std::upper_bound(lane.s.begin(), lane.s.end(), s);
  size_t i = std::min<size_t>(size_t(std::max<long>(it - lane.s.begin() - 1, 0)), lane.s.size() - 2);
  const double seg = lane.s[i + 1] - lane.s[i];
  const double t = seg > 0 ? (s - lane.s[i]) / seg : 0.0;
  return xy(lane.centerline[i]) + t * (xy(lane.centerline[i + 1]) - xy(lane.centerline[i]));
}

double LaneMap::tangent_yaw_at(int index, double s) const {
  const Lane& lane = lanes_.at(size_t(index));
  if (lane.centerline.size() < 2) return 0;
  s = std::clamp(s, 0.0, lane.length());
  auto it = std::upper_bound(lane.s.begin(), lane.s.end(), s);
  size_t i = std::min<size_t>(size_t(std::max<long>(it - lane.s.begin() - 1, 0)), lane.s.size() - 2);
  const Eigen::Vector2d d = xy(lane.centerline[i + 1]) - xy(lane.centerline[i]);
  return std::atan2(d.y(), d.x());
}

double LaneMap::travel_yaw_at(int index, double s) const {
  const double yaw = tangent_yaw_at(index, s);
  if (lanes_.at(size_t(index)).direction == TrafficDirection::Backward)
    return std::remainder(yaw + std::numbers::pi, 2 * std::numbers::pi);
  return yaw;
}

std::vector<LaneCrossing> LaneMap::crossings(int index) const {
  std::vector<LaneCrossing> out;
  const Lane& self = lanes_.at(size_t(index));
  const auto& self_chunks = chunk_bounds_[size_t(index)];
  for (size_t o = 0; o < lanes_.size(); ++o) {
    if (int(o) == index || !bounds_[size_t(index)].intersects(bounds_[o])) continue;
    const Lane& other = lanes_[o];
    // Only the chunks whose extents meet can hold a crossing: the planner asks this for every
    // start it tries a turn from.
    for (size_t ci = 0; ci < self_chunks.size(); ++ci)
      for (size_t cj = 0; cj < chunk_bounds_[o].size(); ++cj) {
        if (!self_chunks[ci].intersects(chunk_bounds_[o][cj])) continue;
        const size_t i_end = std::min((ci + 1) * kSegmentsPerChunk, self.centerline.size() - 1);
        const size_t j_end = std::min((cj + 1) * kSegmentsPerChunk, other.centerline.size() - 1);
        for (size_t i = ci * kSegmentsPerChunk; i < i_end; ++i) {
          const Eigen::Vector2d p = xy(self.centerline[i]);
          const Eigen::Vector2d r = xy(self.centerline[i + 1]) - p;
          for (size_t j = cj * kSegmentsPerChunk; j < j_end; ++j) {
            const Eigen::Vector2d q = xy(other.centerline[j]);
            const Eigen::Vector2d d = xy(other.centerline[j + 1]) - q;
            const double denom = cross2(r, d);
            if (std::abs(denom) < 1e-9) continue;  // parallel lanes never cross
            const double t = cross2(q - p, d) / denom;
            const double u = cross2(q - p, r) / denom;
            if (t < 0 || t >= 1 || u < 0 || u >= 1) continue;
            out.push_back({int(o), self.s[i] + t * r.norm(), other.s[j] + u * d.norm()});
          }
        }
      }
  }
  std::sort(out.begin(), out.end(), [](const LaneCrossing& a, const LaneCrossing& b) { return a.s_self < b.s_self; });
  return out;
}

std::vector<LaneCrossing> LaneMap::junctions(int index, double reach) const {
  std::vector<LaneCrossing> out;
  const Lane& self = lanes_.at(size_t(index));
  const double self_len = self.length();
  // Arc lengths where legal travel on a lane starts and ends: a lane used both ways (a driveway,
  // a car park aisle) starts and ends at either end.
  const auto travel_starts = [](const Lane& l) -> std::vector<double> {
    if (l.direction == TrafficDirection::Both) return {0.0, l.length()};
    return {l.direction == TrafficDirection::Backward ? l.length() : 0.0};
  };
  const auto travel_ends = [](const Lane& l) -> std::vector<double> {
    if (l.direction == TrafficDirection::Both) return {0.0, l.length()};
    return {l.direction == TrafficDirection::Backward ? 0.0 : l.length()};
  };
  const auto inside = [&](const LanePosition& p, double len) { return p.s > 0.5 && p.s < len - 0.5 && std::abs(p.lateral) <= reach; };
  for (size_t o = 0; o < lanes_.size(); ++o) {
    if (int(o) == index) continue;
    const Lane& other = lanes_[o];
    for (const double start : travel_starts(other)) {
      const auto onto_self = project(index, point_at(int(o), start));
      if (inside(onto_self, self_len)) out.push_back({int(o), onto_self.s, start});
    }
    for (const double self_end : travel_ends(self)) {
      const auto onto_other = project(int(o), point_at(index, self_end));
      if (inside(onto_other, other.length())) out.push_back({int(o), self_end, onto_other.s});
    }
  }
  std::sort(out.begin(), out.end(), [](const LaneCrossing& a, const LaneCrossing& b) { return a.s_self < b.s_self; });
  return out;
}

std::optional<LaneMap::JunctionSpan> LaneMap::junction_ahead(const Eigen::Vector2d& p, double yaw) const {
  const auto wrap = [](double a) { return std::remainder(a, 2 * std::numbers::pi); };
  for (const auto& on : containing(p)) {
    const auto& lane = lanes_[size_t(on.lane)];
    if (lane.type != "driving" || std::cos(wrap(travel_yaw_at(on.lane, on.s) - yaw)) < 0.7) continue;
    const int dir = lane.direction == TrafficDirection::Backward ? -1 : 1;
    auto meets = crossings(on.lane);
    for (const auto& j : junctions(on.lane, kJunctionReachM)) meets.push_back(j);
    std::vector<double> ahead;
    for (const auto& m : meets) {
      const double d = dir * (m.s_self - on.s);
      if (d > 0.5 && lanes_[size_t(m.other)].type == "driving" &&
          std::abs(std::cos(wrap(travel_yaw_at(m.other, m.s_other) - travel_yaw_at(on.lane, m.s_self)))) < 0.7)
        ahead.push_back(d);
    }
    if (ahead.empty()) return std::nullopt;
    std::sort(ahead.begin(), ahead.end());
    JunctionSpan span{ahead.front(), ahead.front()};
    for (double d : ahead)
      if (d - span.from <= 15) span.to = d;
    return span;
  }
  return std::nullopt;
}

bool LaneMap::merges(int index) const {
  const auto& l = lanes_[size_t(index)];
  if (l.type != "driving") return false;
  const double end_s = l.direction == TrafficDirection::Backward ? 0.0 : l.length();
  const Eigen::Vector2d end = point_at(index, end_s);
  const double yaw = travel_yaw_at(index, end_s);
  for (size_t i = 0; i < lanes_.size(); ++i) {
    if (int(i) == index || lanes_[i].type != "driving") continue;
    const auto pos = project(int(i), end);
    if (pos.s <= 1 || pos.s >= lanes_[i].length() - 1 || std::abs(pos.lateral) > 5) continue;
    if (std::abs(pos.lateral) < 2) {
      // A lane drawn tapering into the other (a lane drop): beside it some way back, not its continuation.
      const double back_s = l.direction == TrafficDirection::Backward ? std::min(l.length(), end_s + 30)
                                                                      : std::max(0.0, end_s - 30);
      const double before = std::abs(project(int(i), point_at(index, back_s)).lateral);
      if (before < 2 || before > 5) continue;
    }
    if (std::abs(std::remainder(travel_yaw_at(int(i), pos.s) - yaw, 2 * std::numbers::pi)) < std::numbers::pi / 8)
      return true;
  }
  return false;
}

int LaneMap::diverges(int index) const {
  const auto& l = lanes_[size_t(index)];
  if (l.type != "driving") return 0;
  const bool backward = l.direction == TrafficDirection::Backward;
  const double start_s = backward ? l.length() : 0.0, end_s = backward ? 0.0 : l.length();
  const Eigen::Vector2d start = point_at(index, start_s), end = point_at(index, end_s);
  const double yaw = travel_yaw_at(index, start_s);
  for (size_t i = 0; i < lanes_.size(); ++i) {
    if (int(i) == index || lanes_[i].type != "driving") continue;
    const auto pos = project(int(i), start);
    if (pos.s <= 1 || pos.s >= lanes_[i].length() - 1 || std::abs(pos.lateral) > 5) continue;
    if (std::abs(std::remainder(travel_yaw_at(int(i), pos.s) - yaw, 2 * std::numbers::pi)) >= std::numbers::pi / 8) continue;
    // The parent runs on past the lane's end (the pocket stops at the junction, the road does not).
    const auto at_end = project(int(i), end);
    if (at_end.s <= 1 || at_end.s >= lanes_[i].length() - 1) continue;
    const double side = at_end.lateral * (lanes_[i].direction == TrafficDirection::Backward ? -1 : 1);
    if (std::abs(side) >= 2) return side > 0 ? 1 : -1;
  }
  return 0;
}

std::vector<int> LaneMap::named(const std::string& word) const {
  std::vector<int> out;
  if (word.empty()) return out;
  for (size_t i = 0; i < lanes_.size(); ++i) {
    std::string token;
    bool found = false;
    for (const char c : lanes_[i].id + "_") {
      if (std::isalpha(static_cast<unsigned char>(c))) {
        token += char(std::tolower(static_cast<unsigned char>(c)));
        continue;
      }
      found = found || token == word;
      token.clear();
    }
    if (found) out.push_back(int(i));
  }
  return out;
}

}  // namespace chatsim::scene
