#pragma once
// The lane map (lanes.json): centreline polylines with width, type and traffic direction, and
// the queries the agents need (nearest lane, lanes in a region, direction of travel, crossings).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace chatsim::scene {

enum class TrafficDirection { Forward, Backward, Both };

// How far from a lane's centreline a side street may start and still be turned into from it:
// across two more lanes and a parking lane (LaneMap::junctions' reach for turns and junctions).
constexpr double kJunctionReachM = 18.0;

struct Lane {
  std::string id;
  std::string type = "driving";            // driving, parking, ...
  double width = 3.5;
  std::vector<Eigen::Vector3d> centerline;
  TrafficDirection direction = TrafficDirection::Forward;
  std::vector<double> s;                   // arc length at each centreline point (filled by LaneMap)

  double length() const { return s.empty() ? 0.0 : s.back(); }
  // A place vehicles stand, not drive: a parking lane or a (hard) shoulder.
  bool for_stopping() const { return type == "parking" || type == "shoulder"; }
  // A ring (a roundabout): the centreline ends where it starts.
  bool closes_on_itself() const {
    return centerline.size() > 3 && (centerline.front() - centerline.back()).head<2>().norm() < 1.0;
  }
};

// Where a point is relative to one lane.
struct LanePosition {
  int lane = -1;
  double s = 0;             // arc length of the closest centreline point
  double lateral = 0;       // signed distance, left of the polyline direction positive
  double tangent_yaw = 0;   // polyline direction at s
};

struct LaneCrossing {
  int other = -1;
  double s_self = 0;        // arc length on this lane
  double s_other = 0;       // arc length on the other lane
};

class LaneMap {
 public:
  LaneMap() = default;
  explicit LaneMap(std::vector<Lane> lanes);

  const std::vector<Lane>& lanes() const { return lanes_; }
  bool empty() const { return lanes_.empty(); }
  int find(const std::string& id) const;   // -1 if absent

  LanePosition project(int lane, const Eigen::Vector2d& p) const;
  // The lane whose centreline is closest to p (optionally of one type, e.g. "driving").
  std::optional<LanePosition> nearest(const Eigen::Vector2d& p, const std::string& type = "") const;
  // Lanes p lies on: within half the width of the centreline, inside the lane's extent.
  std::vector<LanePosition> containing(const Eigen::Vector2d& p, double margin = 0.0) const;
  // Whether p lies on some lane (as `containing`, without ranking them all): `hint`, a lane tried
  // first, is set to the lane found. A point along a path is mostly on the lane the one before was.
  bool on_some_lane(const Eigen::Vector2d& p, double margin, int& hint) const;
  // Lanes with some centreline point within radius of p.
  std::vector<int> in_region(const Eigen::Vector2d& p, double radius) const;

  Eigen::Vector2d point_at(int lane, double s) const;   // clamped to the lane's extent
  double tangent_yaw_at(int lane, double s) const;
  // Yaw of legal travel at s: the polyline direction, reversed for backward lanes.
  double travel_yaw_at(int lane, double s) const;
  // Where other lanes' centrelines cross this lane's, in order along it.
  std::vector<LaneCrossing> crossings(int lane) const;
  // Where other lanes meet this one without crossing it (a side street's T junction): a lane
  // whose legal travel starts within `reach` of this lane's centreline, or this lane's travel
  // ending within `reach` of another lane. s_other is where the other lane is joined.
  std::vector<LaneCrossing> junctions(int lane, double reach) const;
  // Whether a driving lane's legal travel ends beside another driving lane of the same way (2-5 m
  // across), or drawn tapering into it from beside it, not at a crossing: an on-ramp, a merging
  // lane, a lane that ends.
  bool merges(int lane) const;
  // Whether a driving lane's legal travel starts beside another driving lane of the same way (2-5
  // m across) and it ends short of that lane's end: a turn pocket or an exit lane opening off it.
  // Returns the side it opens to (+1 left, -1 right), 0 when it does not.
  int diverges(int lane) const;
  // The first junction ahead of a vehicle at p heading yaw, on the driving lane it is on: where
  // driving lanes cross or meet that lane at more than 45 deg (a side street, a crossroads), as
  // distances along the lane from p to the first and the last of those within 15 m of the first.
  struct JunctionSpan {
    double from = 0, to = 0;
  };
  std::optional<JunctionSpan> junction_ahead(const Eigen::Vector2d& p, double yaw) const;
  // Lanes whose id names them by a word ("bus" finds "east_bus_lane", "lay_by" is found by "lay"
  // and "by"): the map's own vocabulary for lanes a user names ("the bus lane", "the lay-by").
  std::vector<int> named(const std::string& word) const;

 private:
  // p's position on lane i when p lies on it (within half its width plus margin, inside its extent).
  std::optional<LanePosition> within(size_t i, const Eigen::Vector2d& p, double margin) const;

  std::vector<Lane> lanes_;
  std::vector<Eigen::AlignedBox2d> bounds_;  // each lane's centreline extent grown by half its width
  // Each lane's centreline in chunks of kSegmentsPerChunk segments, and their bounds: projecting
  // onto a long lane visits only the chunks that can hold its nearest point.
  static constexpr size_t kSegmentsPerChunk = 16;
  std::vector<std::vector<Eigen::AlignedBox2d>> chunk_bounds_;
};

}  // namespace chatsim::scene
