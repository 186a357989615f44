#include "bench/chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace chatsim::bench {
namespace {

// The title on one line, smaller when it would not fit.
void put_title(cv::Mat& img, const std::string& title, int left, const cv::Scalar& ink) {
  double scale = 0.7;
  int baseline = 0;
  while (scale > 0.35 && cv::getTextSize(title, cv::FONT_HERSHEY_SIMPLEX, scale, 2, &baseline).width > img.cols - left - 10) scale -= 0.05;
  cv::putText(img, title, {left, 35}, cv::FONT_HERSHEY_SIMPLEX, scale, ink, scale > 0.5 ? 2 : 1, cv::LINE_AA);
}

}  // namespace

int tick_decimals(const std::vector<double>& ticks) {
  double gap = std::numeric_limits<double>::infinity();
  for (size_t k = 1; k < ticks.size(); ++k) gap = std::min(gap, std::abs(ticks[k] - ticks[k - 1]));
  if (!(gap > 0) || !std::isfinite(gap)) return 2;
  // Ticks at least one unit of the last printed digit apart round to different labels; more
  // digits while a label would sit off its line by more than a twentieth of the spacing.
  int d = std::clamp(int(std::ceil(-std::log10(gap) - 1e-9)), 0, 6);
  auto off = [&](int digits) {
    const double unit = std::pow(10.0, -digits);
    double worst = 0;
    for (double t : ticks) worst = std::max(worst, std::abs(std::round(t / unit) * unit - t));
    return worst;
  };
  while (d < 6 && off(d) > gap / 20) ++d;
  return d;
}

std::pair<double, double> nice_axis(double lo, double hi, int divisions) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || divisions < 1) return {lo, hi};
  const double raw = (hi - lo) / divisions;
  double unit = std::pow(10.0, std::floor(std::log10(raw)));
  for (int tries = 0; tries < 8; ++tries) {
    for (double m : {1.0, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0}) {
      const double step = m * unit;
      if (step < raw * (1 - 1e-9)) continue;
      const double start = std::floor(lo / step + 1e-9) * step;
      if (start + divisions * step >= hi - 1e-9 * step) return {start, start + divisions * step};
    }
    unit *= 10;
  }
  return {lo, hi};
}

std::vector<PixelRect> place_labels(const std::vector<std::pair<int, int>>& at, const std::vector<std::pair<int, int>>& text,
                                    const PixelRect& area) {
  const auto overlap = [](const PixelRect& a, const PixelRect& b) {
    const int w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x), h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
    return w > 0 && h > 0 ? long(w) * h : 0L;
  };
  constexpr int kMarker = 7, kGap = 4;
  std::vector<PixelRect> placed;
  for (size_t i = 0; i < at.size(); ++i) {
    const auto [cx, cy] = at[i];
    const auto [tw, th] = text[i];
    // Right, then left, of the marker: level with it, above, below, then further away.
    const int xs[] = {cx + kMarker + kGap, cx - kMarker - kGap - tw};
    const int ys[] = {cy - th / 2, cy - kMarker - th, cy + kMarker, cy - kMarker - 2 * th - kGap, cy + kMarker + th + kGap};
    PixelRect best;
    long best_cost = -1;
    for (const int x : xs)
      for (const int y : ys) {
        const PixelRect r{x, y, tw, th};
        long cost = 0;
        for (const auto& other : placed) cost += overlap(r, other);
        for (const auto& [mx, my] : at) cost += overlap(r, {mx - kMarker, my - kMarker, 2 * kMarker + 1, 2 * kMarker + 1});
        // Outside the plot costs more than any overlap inside it.
        const long outside = long(tw) * th - overlap(r, area);
        cost += outside * 1000;
        if (best_cost < 0 || cost < best_cost) best = r, best_cost = cost;
      }
    placed.push_back(best);
  }
  return placed;
}

void write_scatter_png(const std::filesystem::path& file, const ChartSpec& spec, const std::vector<ChartPoint>& pts) {
  const int w = 900, h = 600, left = 90, right = 40, top = 60, bottom = 80;
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  auto tx = [&](double x) { return spec.log_x ? std::log10(std::max(x, 1e-9)) : x; };
  double x0 = 1e300, x1 = -1e300;
  for (const auto& p : pts) {
    x0 = std::min(x0, tx(p.x));
    x1 = std::max(x1, tx(p.x));
  }
  if (pts.empty()) x0 = 0, x1 = 1;
  const double pad = std::max(1e-6, (x1 - x0) * 0.15);
  x0 -= pad;
  x1 += pad;
  if (!spec.log_x) std::tie(x0, x1) = nice_axis(std::max(0.0, x0), x1, 5);
  // Shares (0..1) keep a fixed axis; anything else (dB, degrees) gets one fitted to the data.
  double y0 = 0.0, y1 = 1.05;
  double lo = 1e300, hi = -1e300;
  for (const auto& p : pts) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
  if (!pts.empty() && (lo < 0 || hi > 1)) {
    const double ypad = std::max(0.5, (hi - lo) * 0.15);
    std::tie(y0, y1) = nice_axis(lo - ypad, hi + ypad, 10);
  }
  auto px = [&](double x) { return int(left + (tx(x) - x0) / (x1 - x0) * (w - left - right)); };
  auto py = [&](double y) { return int(h - bottom - (y - y0) / (y1 - y0) * (h - top - bottom)); };
  const cv::Scalar ink(40, 40, 40), grid(225, 225, 225);
  std::vector<double> y_ticks;
  for (int k = 0; k <= 10; ++k) y_ticks.push_back(y0 + (y1 - y0) * k / 10.0);
  const int y_decimals = tick_decimals(y_ticks);
  for (const double y : y_ticks) {
    cv::line(img, {left, py(y)}, {w - right, py(y)}, grid, 1);
    cv::putText(img, cv::format("%.*f", y_decimals, y), {left - 55, py(y) + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1, cv::LINE_AA);
  }
  std::vector<double> x_ticks;
  for (int k = 0; k <= 5; ++k) {
    const double t = x0 + (x1 - x0) * k / 5;
    x_ticks.push_back(spec.log_x ? std::pow(10, t) : t);
  }
  const int x_decimals = tick_decimals(x_ticks);
  for (int k = 0; k <= 5; ++k) {
    const int X = left + int(double(k) / 5 * (w - left - right));
    cv::line(img, {X, top}, {X, h - bottom}, grid, 1);
    cv::putText(img, cv::format("%.*f", x_decimals, x_ticks[size_t(k)]), {X - 18, h - bottom + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1,
                cv::LINE_AA);
  }
  cv::rectangle(img, {left, top}, {w - right, h - bottom}, ink, 1);
  put_title(img, spec.title, left, ink);
  cv::putText(img, spec.x_label + (spec.log_x ? " (log)" : ""), {w / 2 - 120, h - 25}, cv::FONT_HERSHEY_SIMPLEX, 0.55, ink, 1,
              cv::LINE_AA);
  cv::Mat ylabel(30, h - top - bottom, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(ylabel, spec.y_label, {10, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.55, ink, 1, cv::LINE_AA);
  cv::rotate(ylabel, ylabel, cv::ROTATE_90_COUNTERCLOCKWISE);
  ylabel.copyTo(img(cv::Rect(5, top, 30, h - top - bottom)));
  const cv::Scalar colors[] = {{200, 80, 30}, {30, 140, 40}, {30, 60, 200}, {160, 40, 160}, {20, 150, 200}, {90, 90, 90}};
  std::vector<std::pair<int, int>> at, sizes;
  std::vector<int> baselines;
  for (const auto& p : pts) {
    int baseline = 0;
    const cv::Size text = cv::getTextSize(p.label, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline);
    at.emplace_back(px(p.x), py(p.y));
    sizes.emplace_back(text.width, text.height + baseline);
    baselines.push_back(baseline);
  }
  // Labels may reach into the right margin, not past the image.
  const std::vector<PixelRect> labels = place_labels(at, sizes, {left, top, w - left - 5, h - top - bottom});
  for (size_t i = 0; i < pts.size(); ++i) {
    cv::circle(img, {at[i].first, at[i].second}, 6, colors[i % 6], cv::FILLED, cv::LINE_AA);
    cv::putText(img, pts[i].label, {labels[i].x, labels[i].y + labels[i].h - baselines[i]}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
                colors[i % 6], 1, cv::LINE_AA);
  }
  std::filesystem::create_directories(std::filesystem::absolute(file).parent_path());
  if (!cv::imwrite(file.string(), img)) throw std::runtime_error("could not write the chart " + file.string());
}

void write_stacked_bars_png(const std::filesystem::path& file, const std::string& title, const std::string& x_label,
                            const std::vector<StackedBar>& bars, const char* total_format) {
  // The label column is as wide as the longest label, so none is cut off.
  int label_w = 0;
  for (const auto& b : bars) {
    int baseline = 0;
    label_w = std::max(label_w, cv::getTextSize(b.label, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline).width);
  }
  const int left = std::max(260, 10 + label_w + 16), w = left + 740, right = 40, top = 60, bar_h = 34, gap = 18,
            legend_h = 40;
  const int h = top + int(bars.size()) * (bar_h + gap) + 60 + legend_h;
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Scalar ink(40, 40, 40), grid(225, 225, 225);
  const cv::Scalar colors[] = {{200, 80, 30}, {30, 140, 40}, {30, 60, 200}, {160, 40, 160}, {20, 150, 200}, {90, 90, 90}};
  double x1 = 1e-9;
  std::vector<std::string> stages;
  for (const auto& b : bars) {
    double total = 0;
    for (const auto& [stage, v] : b.segments) {
      total += v;
      if (std::find(stages.begin(), stages.end(), stage) == stages.end()) stages.push_back(stage);
    }
    x1 = std::max(x1, total * 1.1);
  }
  auto px = [&](double x) { return int(left + x / x1 * (w - left - right)); };
  const int bottom_axis = top + int(bars.size()) * (bar_h + gap);
  std::vector<double> ticks;
  for (int k = 0; k <= 5; ++k) ticks.push_back(x1 * k / 5);
  const int x_decimals = tick_decimals(ticks);
  for (const double x : ticks) {
    cv::line(img, {px(x), top}, {px(x), bottom_axis}, grid, 1);
    cv::putText(img, cv::format("%.*f", x_decimals, x), {px(x) - 12, bottom_axis + 18}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1,
                cv::LINE_AA);
  }
  put_title(img, title, 20, ink);
  cv::putText(img, x_label, {w / 2 - 60, bottom_axis + 42}, cv::FONT_HERSHEY_SIMPLEX, 0.55, ink, 1, cv::LINE_AA);
  for (size_t i = 0; i < bars.size(); ++i) {
    const int y = top + int(i) * (bar_h + gap);
    cv::putText(img, bars[i].label, {10, y + bar_h / 2 + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1, cv::LINE_AA);
    double at = 0;
    for (const auto& [stage, v] : bars[i].segments) {
      const size_t c = size_t(std::find(stages.begin(), stages.end(), stage) - stages.begin());
      cv::rectangle(img, {px(at), y}, {std::max(px(at) + 1, px(at + v)), y + bar_h}, colors[c % 6], cv::FILLED);
      at += v;
    }
    cv::putText(img, cv::format(total_format, at), {px(at) + 6, y + bar_h / 2 + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1,
                cv::LINE_AA);
  }
  int lx = 20;
  for (size_t c = 0; c < stages.size(); ++c) {
    cv::rectangle(img, {lx, h - legend_h}, {lx + 14, h - legend_h + 14}, colors[c % 6], cv::FILLED);
    cv::putText(img, stages[c], {lx + 20, h - legend_h + 12}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1, cv::LINE_AA);
    lx += 30 + 9 * int(stages[c].size());
  }
  std::filesystem::create_directories(std::filesystem::absolute(file).parent_path());
  if (!cv::imwrite(file.string(), img)) throw std::runtime_error("could not write the chart " + file.string());
}

}  // namespace chatsim::bench
