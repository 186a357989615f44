// The pipeline benchmark's accuracy: a result against the demo scene's clean plates.
#include <gtest/gtest.h>

#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "bench/plate_accuracy.hpp"
#include "tests/support/scratch_dir.hpp"

namespace chatsim::bench {
namespace {
namespace fs = std::filesystem;

// A 40x30 scene image with a "vehicle" (white block) at (10..19, 10..19), its plate (the road
// without it), and a second removed vehicle whose plate overlaps a third one's.
struct PlateScene {
  fs::path dir = chatsim::scratch::dir() / ("plate-accuracy-" + std::to_string(::getpid()));
  scene::Scene scene;
  cv::Mat captured{30, 40, CV_8UC3, cv::Scalar(90, 90, 90)};
  PlateScene() {
    fs::remove_all(dir);
    fs::create_directories(dir / "images" / "front");
    fs::create_directories(dir / "ground_truth" / "clean_plates");
    captured(cv::Rect(10, 10, 10, 10)).setTo(cv::Scalar(250, 250, 250));
    cv::imwrite((dir / "images" / "front" / "000000.png").string(), captured);
    const cv::Mat plate(12, 12, CV_8UC3, cv::Scalar(90, 90, 90));  // x 9..20, y 9..20
    cv::imwrite((dir / "ground_truth" / "clean_plates" / "a.png").string(), plate);
    cv::imwrite((dir / "ground_truth" / "clean_plates" / "b.png").string(), cv::Mat(5, 5, CV_8UC3, cv::Scalar(90, 90, 90)));
    cv::imwrite((dir / "ground_truth" / "clean_plates" / "c.png").string(), cv::Mat(5, 5, CV_8UC3, cv::Scalar(90, 90, 90)));
    nlohmann::json plates = nlohmann::json::array();
    plates.push_back({{"object", "a"}, {"camera", "front"}, {"frame", 0}, {"path", "ground_truth/clean_plates/a.png"}, {"x", 9}, {"y", 9}, {"width", 12}, {"height", 12}});
    plates.push_back({{"object", "b"}, {"camera", "front"}, {"frame", 0}, {"path", "ground_truth/clean_plates/b.png"}, {"x", 30}, {"y", 2}, {"width", 5}, {"height", 5}});
    plates.push_back({{"object", "c"}, {"camera", "front"}, {"frame", 0}, {"path", "ground_truth/clean_plates/c.png"}, {"x", 32}, {"y", 4}, {"width", 5}, {"height", 5}});
    std::ofstream(dir / "ground_truth" / "clean_plates.json") << nlohmann::json{{"plates", plates}}.dump();
    scene.dir = dir;
    scene::Frame f;
    f.index = 0;
    f.images["front"].path = "images/front/000000.png";
    scene.frames.push_back(f);
  }
  ~PlateScene() { fs::remove_all(dir); }
  fs::path result(const cv::Mat& image) const {
    fs::create_directories(dir / "result" / "frames" / "front");
    cv::imwrite((dir / "result" / "frames" / "front" / "000000.png").string(), image);
    return dir / "result";
  }
};

TEST(PlateAccuracy, APerfectRemovalScoresFarAboveTheCapturedImage) {
  PlateScene ps;
  const cv::Mat perfect(30, 40, CV_8UC3, cv::Scalar(90, 90, 90));
  const auto a = plate_accuracy(ps.scene, ps.result(perfect), {"a", "b", "c"});
  EXPECT_EQ(a.plates, 1);     // b and c overlap each other: left out
  EXPECT_EQ(a.pixels, 100);   // only the pixels the vehicle changed
  EXPECT_GT(a.psnr_db, 100);
  EXPECT_NEAR(a.captured_psnr_db, 10 * std::log10(255.0 * 255 / (160.0 * 160)), 0.01);
}

TEST(PlateAccuracy, AnErrorInsideTheVehicleIsMeasured) {
  PlateScene ps;
  cv::Mat off(30, 40, CV_8UC3, cv::Scalar(90, 90, 90));
  off(cv::Rect(10, 10, 10, 10)).setTo(cv::Scalar(100, 100, 100));
  const auto a = plate_accuracy(ps.scene, ps.result(off), {"a"});
  EXPECT_NEAR(a.psnr_db, 10 * std::log10(255.0 * 255 / 100.0), 0.01);
  EXPECT_THROW(plate_accuracy(ps.scene, ps.dir / "no-result", {"a"}), std::runtime_error);
}

}  // namespace
}  // namespace chatsim::bench
