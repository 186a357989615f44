// The benchmark charts: every point lands inside the plot, whatever its units.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "bench/chart.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {
namespace fs = std::filesystem;

// Pixels of exactly this BGR colour in the image.
int count_colour(const cv::Mat& img, const cv::Vec3b& bgr) {
  int n = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) n += img.at<cv::Vec3b>(y, x) == bgr;
  return n;
}

TEST(Chart, PointsInDecibelsAreDrawnInsideThePlot) {
  const fs::path file = chatsim::scratch::dir() / ("chatsim-chart-" + std::to_string(::getpid()) + ".png");
  chatsim::bench::write_scatter_png(file, {"t", "s", "PSNR [dB]", false}, {{"a", 1.0, 24.0}, {"b", 2.0, 31.0}});
  const cv::Mat img = cv::imread(file.string());
  fs::remove(file);
  ASSERT_FALSE(img.empty());
  // The first point's marker (BGR 200,80,30) is a filled disc: dozens of pixels, not clipped away.
  EXPECT_GT(count_colour(img, {200, 80, 30}), 40);
  EXPECT_GT(count_colour(img, {30, 140, 40}), 40);
}

TEST(Chart, StackedBarsShowEverySegment) {
  const fs::path file = chatsim::scratch::dir() / ("chatsim-bars-" + std::to_string(::getpid()) + ".png");
  chatsim::bench::write_stacked_bars_png(file, "t", "seconds", {{"run", {{"one", 10.0}, {"two", 30.0}}}});
  const cv::Mat img = cv::imread(file.string());
  fs::remove(file);
  ASSERT_FALSE(img.empty());
  const int first = count_colour(img, {200, 80, 30}), second = count_colour(img, {30, 140, 40});
  EXPECT_GT(first, 100);
  EXPECT_GT(second, 2 * first);  // three times as long, minus the legend swatches
}

TEST(Chart, LongBarLabelsAreNotCoveredByTheBars) {
  const fs::path file = chatsim::scratch::dir() / ("chatsim-labels-" + std::to_string(::getpid()) + ".png");
  const std::string label = "fast preset, model cached, stage radiance uncompressed (run 2)";
  chatsim::bench::write_stacked_bars_png(file, "t", "seconds", {{label, {{"one", 10.0}}}});
  const cv::Mat img = cv::imread(file.string());
  fs::remove(file);
  ASSERT_FALSE(img.empty());
  // In the bar's rows (top 60, height 34): the label's dark ink ends before the bar starts.
  int last_ink = -1, first_bar = img.cols;
  for (int y = 60; y < 94; ++y) {
    bool bar_seen = false;  // ink right of the bar is its total ("10.0 s")
    for (int x = 0; x < img.cols; ++x) {
      const auto p = img.at<cv::Vec3b>(y, x);
      if (p == cv::Vec3b(200, 80, 30)) {
        first_bar = std::min(first_bar, x);
        bar_seen = true;
      } else if (!bar_seen && p[0] < 100 && p[1] < 100 && p[2] < 100) {
        last_ink = std::max(last_ink, x);
      }
    }
  }
  EXPECT_GT(last_ink, 300);  // the label is long: wider than the old fixed column
  EXPECT_LT(last_ink, first_bar);
}

TEST(Chart, AxesRunBetweenRoundTicksAroundTheData) {
  using chatsim::bench::nice_axis;
  const auto [db0, db1] = nice_axis(16.9, 18.3, 10);
  EXPECT_DOUBLE_EQ(db0, 16.8);
  EXPECT_DOUBLE_EQ(db1, 18.8);
  const auto [a, b] = nice_axis(2.6, 33.0, 10);
  EXPECT_DOUBLE_EQ(a, 0.0);
  EXPECT_DOUBLE_EQ(b, 40.0);
  for (const auto& [lo, hi, n] : std::vector<std::tuple<double, double, int>>{{0.1055, 0.1389, 5}, {-3.2, 7.9, 10}, {0.5, 0.5004, 5}, {100, 900, 5}}) {
    const auto [y0, y1] = nice_axis(lo, hi, n);
    EXPECT_LE(y0, lo);
    EXPECT_GE(y1, hi);
    EXPECT_LT(y1 - y0, 3 * (hi - lo)) << lo << " to " << hi;  // not needlessly wide
    const double step = (y1 - y0) / n;
    EXPECT_NEAR(y0 / step, std::round(y0 / step), 1e-6) << lo << " to " << hi;  // ticks on multiples of the step
  }
}

// Ticks a narrow range apart got the same label (0.14, 0.14) at two fixed decimals.
TEST(Chart, TickLabelsAreDistinctCloseToTheirValuesAndNoLongerThanNeeded) {
  auto ticks = [](double lo, double hi, int n) {
    std::vector<double> t;
    for (int k = 0; k <= n; ++k) t.push_back(lo + (hi - lo) * k / n);
    return t;
  };
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{{0.1128, 0.1659}, {0.0, 1.05}, {2.7, 32.0}, {100, 900}, {0.5, 0.5004}, {16.9, 18.3}}) {
    const auto t = ticks(lo, hi, 5);
    const double gap = (hi - lo) / 5;
    const int d = chatsim::bench::tick_decimals(t);
    std::set<std::string> labels;
    for (double v : t) {
      labels.insert(cv::format("%.*f", d, v));
      EXPECT_LE(std::abs(std::stod(cv::format("%.*f", d, v)) - v), gap / 20 + 1e-12) << v << " at " << d << " decimals";
    }
    EXPECT_EQ(labels.size(), 6u) << lo << " to " << hi << " at " << d << " decimals";
  }
  EXPECT_EQ(chatsim::bench::tick_decimals(ticks(0, 500, 5)), 0);
  EXPECT_EQ(chatsim::bench::tick_decimals(ticks(0, 30, 10)), 0);       // 3, 6, 9: no ".0"
  EXPECT_EQ(chatsim::bench::tick_decimals(ticks(0.1, 0.153, 5)), 3);   // 0.1106 is "0.111", not "0.11"
  EXPECT_EQ(chatsim::bench::tick_decimals(ticks(16.9, 18.3, 10)), 2);  // 17.04 is "17.04", not "17.0"
  EXPECT_EQ(chatsim::bench::tick_decimals({1.0}), 2);                 // one tick: no spacing to go by
}

}  // namespace

namespace {
bool intersects(const chatsim::bench::PixelRect& a, const chatsim::bench::PixelRect& b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}
bool inside(const chatsim::bench::PixelRect& r, const chatsim::bench::PixelRect& area) {
  return r.x >= area.x && r.y >= area.y && r.x + r.w <= area.x + area.w && r.y + r.h <= area.y + area.h;
}
}  // namespace

// Two configurations that score alike sit side by side: their labels must not cover each other
// (fast-600 and fast-600-dssim did), nor the markers, nor leave the plot.
TEST(Chart, LabelsOfNearbyPointsDoNotOverlap) {
  using chatsim::bench::PixelRect;
  const PixelRect area{90, 60, 805, 460};
  const std::vector<std::pair<int, int>> at{{280, 200}, {318, 194}, {278, 236}, {700, 175}, {890, 300}};
  const std::vector<std::pair<int, int>> text{{70, 14}, {120, 14}, {230, 14}, {40, 14}, {60, 14}};
  const auto labels = chatsim::bench::place_labels(at, text, area);
  ASSERT_EQ(labels.size(), at.size());
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_EQ(labels[i].w, text[i].first);
    EXPECT_TRUE(inside(labels[i], area)) << i;
    for (size_t j = 0; j < i; ++j) EXPECT_FALSE(intersects(labels[i], labels[j])) << i << " and " << j;
    for (const auto& [x, y] : at) EXPECT_FALSE(intersects(labels[i], {x - 6, y - 6, 13, 13})) << i;
  }
  // A lone point's label sits level with it, on its right.
  EXPECT_EQ(labels[3].x, 700 + 11);
  EXPECT_EQ(labels[3].y, 175 - 7);
  // At the plot's right edge it goes to the left.
  EXPECT_LT(labels[4].x + labels[4].w, 890);
}
