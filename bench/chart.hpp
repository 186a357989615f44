#pragma once
// A small PNG chart (OpenCV) of speed against accuracy: one labelled point per method or
// category, so a person can see the trade-off at a glance.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace chatsim::bench {

struct ChartPoint {
  std::string label;
  double x = 0;   // speed axis (e.g. ms per decision; lower is better)
  double y = 0;   // accuracy axis (0..1; higher is better)
};

struct ChartSpec {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
};

// An axis from at most `lo` to at least `hi` whose `divisions` ticks fall on round values
// (steps of 1, 2, 2.5, 3, 4, 5, 6 or 8 times a power of ten), e.g. 16.9-18.3 in 10: 16.8-18.8.
std::pair<double, double> nice_axis(double lo, double hi, int divisions);

// Decimals that print these axis ticks as distinct labels (0.121 and 0.127 at 3, not both
// 0.12), each close to its true value (17.04 rather than 17.0), and no more (3, 6, 9).
int tick_decimals(const std::vector<double>& ticks);

// A rectangle in image pixels (x, y: its top left corner).
struct PixelRect {
  int x = 0, y = 0, w = 0, h = 0;
};

// Where each point's label goes: beside its marker (centres `at`, text sizes `text` as w, h),
// on the first side where it overlaps no label placed before it and no marker and stays inside
// `area`; where no side is free, the one overlapping least. Returns the labels' rectangles.
std::vector<PixelRect> place_labels(const std::vector<std::pair<int, int>>& at, const std::vector<std::pair<int, int>>& text,
                                    const PixelRect& area);

// Writes a PNG; throws std::runtime_error when it cannot.
void write_scatter_png(const std::filesystem::path& file, const ChartSpec& spec, const std::vector<ChartPoint>& points);

// One bar per run, split into named parts (e.g. seconds per pipeline stage), stacked left to
// right in the order given; the same name has the same colour in every bar.
struct StackedBar {
  std::string label;
  std::vector<std::pair<std::string, double>> segments;
};
// total_format: how each bar's total is printed after it (printf, one double).
void write_stacked_bars_png(const std::filesystem::path& file, const std::string& title, const std::string& x_label,
                            const std::vector<StackedBar>& bars, const char* total_format = "%.1f s");

}  // namespace chatsim::bench
