// EXR files: both compressions give back exactly what was written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "render/image_io.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace chatsim;
namespace fs = std::filesystem;

TEST(ImageIo, ExrRoundTripsExactlyWithEitherCompression) {
  cv::Mat img(64, 96, CV_32FC3);
  cv::RNG rng(7);
  rng.fill(img, cv::RNG::UNIFORM, 0.0f, 4.0f);
  img(cv::Rect(0, 0, 96, 32)).setTo(cv::Scalar(0.5f, 0.25f, 1.0f));  // a flat half that zip shrinks
  const fs::path dir = chatsim::scratch::dir() / ("chatsim-image-io-" + std::to_string(getpid()));
  fs::create_directories(dir);
  render::write_exr(dir / "zip.exr", img);
  render::write_exr(dir / "none.exr", img, render::ExrCompression::None);
  for (const char* name : {"zip.exr", "none.exr"}) {
    const cv::Mat back = render::read_float_image(dir / name);
    ASSERT_EQ(back.size(), img.size()) << name;
    EXPECT_EQ(cv::norm(back, img, cv::NORM_INF), 0.0) << name;
  }
  EXPECT_LT(fs::file_size(dir / "zip.exr"), fs::file_size(dir / "none.exr"));
  EXPECT_GE(fs::file_size(dir / "none.exr"), 64u * 96u * 3u * 4u);  // stored as is
  fs::remove_all(dir);
}
