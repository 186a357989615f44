// The benchmark charts: every point lands inside the plot, whatever its units.
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "bench/chart.hpp"

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
  const fs::path file = fs::temp_directory_path() / ("chatsim-chart-" + std::to_string(::getpid()) + ".png");
  chatsim::bench::write_scatter_png(file, {"t", "s", "PSNR [dB]", false}, {{"a", 1.0, 24.0}, {"b", 2.0, 31.0}});
  const cv::Mat img = cv::imread(file.string());
  fs::remove(file);
  ASSERT_FALSE(img.empty());
  // The first point's marker (BGR 200,80,30) is a filled disc: dozens of pixels, not clipped away.
  EXPECT_GT(count_colour(img, {200, 80, 30}), 40);
  EXPECT_GT(count_colour(img, {30, 140, 40}), 40);
}

TEST(Chart, StackedBarsShowEverySegment) {
  const fs::path file = fs::temp_directory_path() / ("chatsim-bars-" + std::to_string(::getpid()) + ".png");
  chatsim::bench::write_stacked_bars_png(file, "t", "seconds", {{"run", {{"one", 10.0}, {"two", 30.0}}}});
  const cv::Mat img = cv::imread(file.string());
  fs::remove(file);
  ASSERT_FALSE(img.empty());
  const int first = count_colour(img, {200, 80, 30}), second = count_colour(img, {30, 140, 40});
  EXPECT_GT(first, 100);
  EXPECT_GT(second, 2 * first);  // three times as long, minus the legend swatches
}

}  // namespace
