#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "common/scene/lane_map.hpp"

using namespace chatsim::scene;

namespace {

// A winding lane with many short segments, so its centreline spans many chunks and doubles back
// near itself (where the nearest chunk by bounds is not the one holding the nearest point).
Lane winding_lane(const std::string& id, double y0) {
  Lane l;
  l.id = id;
  for (int i = 0; i <= 400; ++i) {
    const double t = i * 0.25;
    l.centerline.emplace_back(t, y0 + 6 * std::sin(t / 4), 0);
  }
  return l;
}

// Projection by visiting every segment in order, as LaneMap did before it skipped chunks.
LanePosition project_every_segment(const Lane& lane, const Eigen::Vector2d& p) {
  LanePosition best{0, 0, 0, 0};
  double best_d2 = std::numeric_limits<double>::infinity(), s = 0;
  for (size_t i = 0; i + 1 < lane.centerline.size(); ++i) {
    const Eigen::Vector2d a = lane.centerline[i].head<2>(), d = lane.centerline[i + 1].head<2>() - a;
    const double len = d.norm();
    const double t = std::clamp((p - a).dot(d) / (len * len), 0.0, 1.0);
    const double d2 = (p - (a + t * d)).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.s = s + t * len;
      best.lateral = (d.x() * (p - a).y() - d.y() * (p - a).x()) / len;
      best.tangent_yaw = std::atan2(d.y(), d.x());
    }
    s += len;
  }
  return best;
}

}  // namespace

TEST(LaneMap, ProjectingByChunksFindsWhatEverySegmentFinds) {
  const LaneMap map({winding_lane("a", 0)});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(-10, 110), y(-15, 15);
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector2d p(x(rng), y(rng));
    const LanePosition got = map.project(0, p), want = project_every_segment(map.lanes()[0], p);
    ASSERT_NEAR(got.s, want.s, 1e-9) << p.transpose();
    ASSERT_NEAR(got.lateral, want.lateral, 1e-9) << p.transpose();
    ASSERT_NEAR(got.tangent_yaw, want.tangent_yaw, 1e-12) << p.transpose();
  }
  // Beyond a corner both segments meeting there are as close: the earlier one is taken.
  const Lane corner{"c", "driving", 3.5, {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}}, TrafficDirection::Forward, {}};
  const LaneMap bent({corner});
  EXPECT_NEAR(bent.project(0, {12, -2}).tangent_yaw, 0, 1e-12);
}

TEST(LaneMap, OnSomeLaneAgreesWithContainingAndRemembersTheLane) {
  const LaneMap map({winding_lane("a", 0), winding_lane("b", 20)});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-5, 105), y(-10, 30);
  int on = 0;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector2d p(x(rng), y(rng));
    int hint = k % 3 - 1;  // none, a, or b tried first
    const bool found = map.on_some_lane(p, 0.3, hint);
    const auto all = map.containing(p, 0.3);
    ASSERT_EQ(found, !all.empty()) << p.transpose();
    if (!found) continue;
    ++on;
    bool listed = false;
    for (const auto& pos : all) listed = listed || pos.lane == hint;
    EXPECT_TRUE(listed) << "the lane remembered is one p lies on";
  }
  EXPECT_GT(on, 100);  // the sample reaches both outcomes
}

TEST(LaneMap, CrossingsByChunksAreTheCrossingsOfEverySegmentPair) {
  // A winding lane crossed by straight lanes at several angles and by another winding lane.
  std::vector<Lane> lanes{winding_lane("wind_a", 0), winding_lane("wind_b", 3)};
  for (int k = 0; k < 6; ++k) {
    Lane l;
    l.id = "cross_" + std::to_string(k);
    const double x = 10 + 15 * k, tilt = 4.0 * (k - 2);
    for (int i = 0; i <= 8; ++i) l.centerline.emplace_back(x + tilt * (i - 4) / 4.0, -20 + 5 * i, 0);
    lanes.push_back(l);
  }
  const LaneMap map(lanes);
  for (size_t self = 0; self < lanes.size(); ++self) {
    size_t brute = 0;  // every segment pair of this lane and each other one
    for (size_t o = 0; o < lanes.size(); ++o) {
      if (o == self) continue;
      const auto& a = map.lanes()[self].centerline;
      const auto& b = map.lanes()[o].centerline;
      for (size_t i = 0; i + 1 < a.size(); ++i)
        for (size_t j = 0; j + 1 < b.size(); ++j) {
          const Eigen::Vector2d p = a[i].head<2>(), r = a[i + 1].head<2>() - p;
          const Eigen::Vector2d q = b[j].head<2>(), d = b[j + 1].head<2>() - q;
          const double denom = r.x() * d.y() - r.y() * d.x();
          if (std::abs(denom) < 1e-9) continue;
          const Eigen::Vector2d w = q - p;
          const double t = (w.x() * d.y() - w.y() * d.x()) / denom, u = (w.x() * r.y() - w.y() * r.x()) / denom;
          if (t >= 0 && t < 1 && u >= 0 && u < 1) ++brute;
        }
    }
    EXPECT_EQ(map.crossings(int(self)).size(), brute) << lanes[self].id;
    EXPECT_GT(brute, 0u) << lanes[self].id;
  }
}
