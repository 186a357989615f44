#include "bench/chart.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace chatsim::bench {

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
  if (!spec.log_x) x0 = std::max(0.0, x0);
  const double y0 = 0.0, y1 = 1.05;
  auto px = [&](double x) { return int(left + (tx(x) - x0) / (x1 - x0) * (w - left - right)); };
  auto py = [&](double y) { return int(h - bottom - (y - y0) / (y1 - y0) * (h - top - bottom)); };
  const cv::Scalar ink(40, 40, 40), grid(225, 225, 225);
  for (int k = 0; k <= 10; ++k) {
    const double y = k / 10.0;
    cv::line(img, {left, py(y)}, {w - right, py(y)}, grid, 1);
    cv::putText(img, cv::format("%.1f", y), {left - 45, py(y) + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, ink, 1, cv::LINE_AA);
  }
  for (int k = 0; k <= 5; ++k) {
    const double t = x0 + (x1 - x0) * k / 5;
    const double x = spec.log_x ? std::pow(10, t) : t;
    const int X = left + int(double(k) / 5 * (w - left - right));
    cv::line(img, {X, top}, {X, h - bottom}, grid, 1);
    cv::putText(img, cv::format(x < 10 ? "%.2f" : "%.0f", x), {X - 18, h - bottom + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
                ink, 1, cv::LINE_AA);
  }
  cv::rectangle(img, {left, top}, {w - right, h - bottom}, ink, 1);
  cv::putText(img, spec.title, {left, 35}, cv::FONT_HERSHEY_SIMPLEX, 0.7, ink, 2, cv::LINE_AA);
  cv::putText(img, spec.x_label + (spec.log_x ? " (log)" : ""), {w / 2 - 120, h - 25}, cv::FONT_HERSHEY_SIMPLEX, 0.55, ink, 1,
              cv::LINE_AA);
  cv::Mat ylabel(30, h - top - bottom, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(ylabel, spec.y_label, {10, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.55, ink, 1, cv::LINE_AA);
  cv::rotate(ylabel, ylabel, cv::ROTATE_90_COUNTERCLOCKWISE);
  ylabel.copyTo(img(cv::Rect(5, top, 30, h - top - bottom)));
  const cv::Scalar colors[] = {{200, 80, 30}, {30, 140, 40}, {30, 60, 200}, {160, 40, 160}, {20, 150, 200}, {90, 90, 90}};
  for (size_t i = 0; i < pts.size(); ++i) {
    const cv::Point c(px(pts[i].x), py(pts[i].y));
    cv::circle(img, c, 6, colors[i % 6], cv::FILLED, cv::LINE_AA);
    int baseline = 0;
    const cv::Size text = cv::getTextSize(pts[i].label, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline);
    // Labels near the right edge go on the point's left, so none is cut off.
    const int dx = c.x + 9 + text.width > w - 5 ? -9 - text.width : 9;
    cv::putText(img, pts[i].label, c + cv::Point(dx, -8 + int(i % 3) * 12), cv::FONT_HERSHEY_SIMPLEX, 0.45, colors[i % 6], 1,
                cv::LINE_AA);
  }
  std::filesystem::create_directories(std::filesystem::absolute(file).parent_path());
  if (!cv::imwrite(file.string(), img)) throw std::runtime_error("could not write the chart " + file.string());
}

}  // namespace chatsim::bench
