// The rendered demo scene: a valid scene with the realism traps it promises and ground truth
// that agrees with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "agents/render/foreground_role.hpp"
#include "agents/render/render_cache.hpp"
#include "common/scene/camera_model.hpp"
#include "render/demo/demo_generate.hpp"
#include "render/gs/moving_mask.hpp"
#include "render/gs/nvs_eval.hpp"
#include "render/gs/trainer.hpp"
#include "render/image_io.hpp"
#include "render/image_metrics.hpp"
#include "render/inpaint/deletion_eval.hpp"
#include "render/inpaint/moved_view_eval.hpp"
#include "render/light/light_eval.hpp"
#include "tests/support/scratch_dir.hpp"

namespace chatsim {
namespace {
namespace fs = std::filesystem;

class DemoScene : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(chatsim::scratch::dir() / ("chatsim-demo-test-" + std::to_string(getpid())));
    auto o = render::demo::small_demo_options(3);
    o.layout.frames = 4;
    o.layout.width = 96;
    o.layout.height = 64;
    o.holdout_every = 4;
    o.holdout_phase = 1;
    o.shifted_frames = {2};
    o.plate_every = 2;
    o.image_format = "png";  // lossless, so plates can be compared pixel for pixel
    report_ = render::demo::generate_demo_scene(o, *dir_);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static nlohmann::json read(const fs::path& f) { return read_json(*dir_ / f); }
  static nlohmann::json read_json(const fs::path& f) { return nlohmann::json::parse(std::ifstream(f)); }
  // A radiance field of the draft preset, trained for a few iterations: enough to render.
  static render::gs::RadianceField quick_model(const scene::Scene& s, int iterations) {
    render::gs::TrainOptions t;
    t.preset = "draft";
    t.max_iterations = iterations;
    return render::gs::train(s, t);
  }
  static fs::path* dir_;
  static render::demo::DemoReport report_;
};
fs::path* DemoScene::dir_ = nullptr;
render::demo::DemoReport DemoScene::report_;

// D-SSIM in the loss (TrainOptions::ssim_weight) takes effect and keeps training finite.
TEST_F(DemoScene, TrainingWithDssimStaysFiniteAndDiffersFromL1) {
  const auto s = scene::load_scene(*dir_);
  auto trained = [&](float weight) {
    render::gs::TrainOptions t;
    t.preset = "draft";
    t.max_iterations = 40;
    t.ssim_weight = weight;
    render::gs::TrainReport report;
    auto model = render::gs::train(s, t, &report);
    EXPECT_EQ(report.iterations, 40);
    EXPECT_TRUE(std::isfinite(report.train_psnr));
    EXPECT_EQ(std::count_if(model.gaussians.p.begin(), model.gaussians.p.end(), [](float v) { return !std::isfinite(v); }), 0);
    return model;
  };
  const auto l1 = trained(0), mixed = trained(0.2f);
  EXPECT_NE(l1.gaussians.p, mixed.gaussians.p);
}

TEST_F(DemoScene, IsAValidSceneWithImagesLidarAndDifferentExposures) {
  const auto s = scene::load_scene(*dir_);  // checks every image and LiDAR file exists
  EXPECT_FALSE(s.layout_only);
  ASSERT_EQ(s.frames.size(), 4u);
  ASSERT_EQ(s.cameras.size(), 3u);
  EXPECT_EQ(report_.images, 12);
  const auto& f = s.frames[1];
  const double e_front = *f.images.at("front").exposure_s, e_left = *f.images.at("front_left").exposure_s;
  EXPECT_GT(e_left / e_front, 1.15);  // the side cameras expose differently
  const auto img = render::read_rgb8(*dir_ / f.images.at("front").path);
  EXPECT_EQ(img.cols, 96);
  EXPECT_GT(cv::mean(img)[1], 30);    // neither black ...
  EXPECT_LT(cv::mean(img)[1], 230);   // ... nor blown out
  const auto pts = scene::read_lidar(*dir_ / f.lidar);
  EXPECT_GT(pts.size(), 5000u);
}

TEST_F(DemoScene, RecordedPosesAreSlightlyWrongAndTheTruthIsKept) {
  const auto poses = read("ground_truth/poses.json")["images"];
  ASSERT_EQ(poses.size(), 12u);
  double max_error = 0;
  for (const auto& p : poses) {
    Eigen::Matrix4d t, r;
    for (int k = 0; k < 16; ++k) t(k / 4, k % 4) = p["camera_to_world_true"][size_t(k)], r(k / 4, k % 4) = p["camera_to_world_recorded"][size_t(k)];
    max_error = std::max(max_error, (t.block<3, 1>(0, 3) - r.block<3, 1>(0, 3)).norm());
  }
  // 8 m/s x (12 ms offset + up to 2 ms jitter): about a decimetre, never a metre.
  EXPECT_GT(max_error, 0.05);
  EXPECT_LT(max_error, 0.2);
}

TEST_F(DemoScene, DepthMatchesTheLidar) {
  // LiDAR points seen by the front camera at frame 0 lie at the ground-truth depth there.
  const auto s = scene::load_scene(*dir_);
  const auto poses = read("ground_truth/poses.json")["images"];
  Eigen::Isometry3d c2w = Eigen::Isometry3d::Identity();
  for (const auto& p : poses)
    if (p["camera"] == "front" && p["frame"] == 0)
      for (int k = 0; k < 16; ++k) c2w.matrix()(k / 4, k % 4) = p["camera_to_world_true"][size_t(k)];
  const cv::Mat depth = render::read_float_image(*dir_ / "ground_truth/depth/front/000000.exr");
  int checked = 0, agree = 0;
  for (const auto& lp : scene::read_lidar(*dir_ / s.frames[0].lidar)) {
    const Eigen::Vector3d w = s.frames[0].ego_to_world * lp.xyz.cast<double>();
    const auto pr = scene::project(*s.camera("front"), c2w, w);
    if (!pr || !pr->in_image || pr->depth > 40) continue;
    const float d = depth.at<float>(int(pr->pixel.y() + 0.5), int(pr->pixel.x() + 0.5));
    ++checked;
    // The camera fires at a slightly different time from the LiDAR: allow a little.
    if (std::abs(d - pr->depth) < 0.05 * pr->depth + 0.15) ++agree;
  }
  ASSERT_GT(checked, 50);
  EXPECT_GT(double(agree) / checked, 0.8);
}

TEST_F(DemoScene, CleanPlatesDifferOnlyWhereTheObjectWas) {
  const auto plates = read("ground_truth/clean_plates.json")["plates"];
  ASSERT_GT(plates.size(), 0u);
  const auto s = scene::load_scene(*dir_);
  int checked = 0, changed = 0;
  for (const auto& p : plates) {
    const cv::Rect r(p["x"], p["y"], p["width"], p["height"]);
    const auto& frame = s.frames[size_t(p["frame"].get<int>())];
    const cv::Mat img = render::read_rgb8(*dir_ / frame.images.at(p["camera"].get<std::string>()).path);
    const cv::Mat plate = render::read_rgb8(*dir_ / p["path"].get<std::string>());
    ASSERT_EQ(plate.size(), r.size());
    const cv::Mat diff = cv::abs(img(r) - plate) + cv::abs(plate - img(r));
    // Removing an object changes its pixels, unless something else hides it.
    if (cv::norm(diff, cv::NORM_INF) > 20) ++changed;
    // The crop's outer ring (padding beyond the box and its shadow) is the same picture, noise
    // and all: at most small differences from the smoothing of light near the object.
    if (r.width > 8 && r.height > 8) {
      cv::Mat ring = cv::Mat::ones(r.size(), CV_8U) * 255;
      ring(cv::Rect(2, 2, r.width - 4, r.height - 4)).setTo(0);
      cv::Mat gray;
      cv::cvtColor(diff, gray, cv::COLOR_RGB2GRAY);
      std::vector<uchar> v;
      for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
          if (ring.at<uchar>(y, x)) v.push_back(gray.at<uchar>(y, x));
      std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
      EXPECT_LE(v[v.size() / 2], 4) << p["object"] << " " << p["camera"] << " frame " << p["frame"];
    }
    ++checked;
  }
  ASSERT_GT(checked, 0);
  EXPECT_GT(changed, checked / 2);
}

TEST_F(DemoScene, GroundTruthViewsAndSkyAreWritten) {
  const auto views = read("ground_truth/views.json")["views"];
  // Held-out frame 1 (3 cameras, unshifted) and frame 2 (3 cameras x 4 shifts).
  EXPECT_EQ(views.size(), 3u + 12u);
  for (const auto& v : views) {
    EXPECT_TRUE(fs::exists(*dir_ / v["image"].get<std::string>()));
    EXPECT_TRUE(fs::exists(*dir_ / v["depth"].get<std::string>()));
  }
  const auto sky = read("ground_truth/sky.json");
  EXPECT_EQ(sky["sky_type"], "sunny");
  EXPECT_GT(sky["sun_direction_world"][2].get<double>(), 0.5);
  const auto env = render::EnvMap::read(*dir_ / "ground_truth/sky.exr");
  EXPECT_EQ(env.width(), 512);
}

// The light evaluation reads that sky: one result per evaluated frame, each an angle; a scene
// without it is refused with the file named. (At 96x64 the angles say nothing about accuracy:
// bench light --scene measures that on the full demo scene.)
TEST_F(DemoScene, LightEvaluationComparesWithTheGroundTruthSkyAndNamesItWhenMissing) {
  const auto r = render::light::evaluate_on_scene(scene::load_scene(*dir_), 2);
  ASSERT_EQ(r["frames"].size(), 2u) << r.dump(1);  // frames 0 and 2 of 4
  for (const auto& f : r["frames"]) {
    EXPECT_GE(f["peak_angular_error_deg"].get<double>(), 0.0);
    EXPECT_LE(f["peak_angular_error_deg"].get<double>(), 180.0);
  }
  // And the estimate the agents use, from frames spread over the clip (4 of its 4 here).
  EXPECT_EQ(r["clip"]["frames"], nlohmann::json({0, 1, 2, 3})) << r.dump(1);
  EXPECT_GE(r["clip"]["peak_angular_error_deg"].get<double>(), 0.0);
  EXPECT_LE(r["clip"]["peak_angular_error_deg"].get<double>(), 180.0);
  const fs::path copy = chatsim::scratch::dir() / ("chatsim-light-eval-test-" + std::to_string(getpid()));
  fs::remove_all(copy);
  fs::copy(*dir_, copy, fs::copy_options::recursive);
  fs::remove(copy / "ground_truth" / "sky.json");
  try {
    render::light::evaluate_on_scene(scene::load_scene(copy), 2);
    ADD_FAILURE() << "a scene without ground_truth/sky.json was evaluated";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ground_truth/sky.json"), std::string::npos) << e.what();
  }
  fs::remove_all(copy);
}

// The deletion agent renders the radiance field only around its masks: that region's pixels
// are the full render's, and the rest is left zero.
TEST_F(DemoScene, ARegionRenderIsTheFullRenderThere) {
  const auto s = scene::load_scene(*dir_);
  const auto model = quick_model(s, 30);
  const auto& f = s.frames[1];
  const auto* cam = s.camera("front");
  const auto pose = s.camera_to_world(f, *cam);
  const double time = f.images.at("front").timestamp_s;
  const auto full = model.render(s, *cam, pose, time);
  const cv::Rect roi(30, 20, 41, 29);
  const auto part = model.render_region(s, *cam, pose, time, {}, roi);
  ASSERT_EQ(part.radiance.size(), full.radiance.size());
  // The same to 1 % per pixel and 0.01 % on average (here the crop's top row differed by up
  // to 0.15 %, the rest by far less).
  cv::Mat diff = cv::abs(full.radiance(roi) - part.radiance(roi)), rel;
  cv::divide(diff, cv::abs(full.radiance(roi)) + cv::Scalar::all(1e-3), rel);
  double worst = 0;
  cv::minMaxLoc(rel.reshape(1), nullptr, &worst);
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(cv::mean(rel.reshape(1))[0], 1e-4);
  EXPECT_LT(cv::norm(full.alpha(roi), part.alpha(roi), cv::NORM_INF), 0.01);
  cv::Mat outside(full.radiance.size(), CV_8U, cv::Scalar(255));
  outside(roi).setTo(0);
  cv::Mat lum;
  cv::cvtColor(cv::abs(part.radiance), lum, cv::COLOR_RGB2GRAY);
  EXPECT_EQ(cv::countNonZero((lum > 0) & outside), 0);
  EXPECT_GT(cv::countNonZero(lum(roi) > 0), roi.area() / 2);
}

// Deletion in the field's renders of the shifted truth views: every shifted view is taken, a
// view with enough changed pixels gets every fill's score, and a scene without those views is
// refused naming the file. (At 96x64 most changes lie inside the vehicles' own outlines, so
// few views are scored here; the benchmark measures it at full size.)
TEST_F(DemoScene, MovedViewDeletionScoresEveryFillOnTheShiftedTruthViews) {
  const auto s = scene::load_scene(*dir_);
  const auto model = std::make_shared<render::gs::RadianceField>(quick_model(s, 30));
  const auto r = render::inpaint::evaluate_moved_view_deletion(s, model);
  const auto views = read("ground_truth/views.json")["views"];
  const auto shifted = std::count_if(views.begin(), views.end(), [](const nlohmann::json& v) { return v["shift"] != "none"; });
  EXPECT_EQ(r["summary"]["views"].get<long>(), shifted);
  ASSERT_EQ(long(r["views"].size()), shifted);
  long pixels = 0;
  for (const auto& v : r["views"]) {
    pixels += v["pixels"].get<long>();
    const bool scored = v["pixels"].get<int>() >= 50;
    for (const char* k : {"psnr_field", "psnr_outline_only", "psnr_path_ungated", "psnr_agent"}) {
      EXPECT_EQ(v.contains(k), scored) << v.dump();
      if (scored) {
        EXPECT_TRUE(std::isfinite(v[k].get<double>())) << v.dump();
      }
    }
  }
  EXPECT_GT(pixels, 0) << "the deletion changed no pixel outside the vehicles' outlines in any view";
  scene::Scene bare = s;
  bare.dir = chatsim::scratch::dir() / "no-truth-views";
  try {
    render::inpaint::evaluate_moved_view_deletion(bare, model);
    FAIL() << "a scene without shifted truth views must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("views.json"), std::string::npos) << e.what();
  }
}

// The novel-view evaluation also scores the captured held-out images against their noise-free
// views: what a perfect model would reach on the held-out set.
TEST_F(DemoScene, NvsEvalReportsWhatAPerfectModelWouldScoreOnTheHeldOutImages) {
  const auto s = scene::load_scene(*dir_);
  const auto model = quick_model(s, 10);
  render::gs::NvsOptions o;
  o.holdout = 2;  // frames 1 and 3; the fixture's noise-free unshifted views are of frame 1
  const auto r = render::gs::evaluate_nvs(model, s, o);
  ASSERT_TRUE(r.contains("held_out_ceiling")) << r.dump(1);
  double expected = 0;
  int n = 0;
  const auto doc = read("ground_truth/views.json");
  for (const auto& v : doc["views"]) {
    if (v["shift"] != "none") continue;
    const auto& f = s.frames[size_t(v["frame"].get<int>())];
    expected += render::psnr(render::read_rgb8(*dir_ / f.images.at(v["camera"]).path), render::read_rgb8(*dir_ / v["image"].get<std::string>()));
    ++n;
  }
  ASSERT_EQ(n, 3);
  EXPECT_EQ(r["held_out_ceiling"]["count"].get<int>(), n);
  EXPECT_NEAR(r["held_out_ceiling"]["psnr"].get<double>(), expected / n, 1e-9);
  EXPECT_LT(r["held_out_ceiling"]["ssim"].get<double>(), 1.0);  // the captured images are noisy
  // The static background's score leaves out where moving objects are; each set averages its
  // views that have one.
  for (const auto& [set, summary] : r["sets"].items()) {
    double sum = 0;
    int with_static = 0;
    for (const auto& v : r["views"])
      if (v["set"] == set && v.contains("psnr_static")) sum += v["psnr_static"].get<double>(), ++with_static;
    if (with_static == 0) {
      EXPECT_FALSE(summary.contains("psnr_static")) << set;
      continue;
    }
    EXPECT_EQ(summary["static_count"].get<int>(), with_static) << set;
    EXPECT_NEAR(summary["psnr_static"].get<double>(), sum / with_static, 1e-9) << set;
  }
  const auto moving = render::gs::moving_objects(s);
  EXPECT_TRUE(std::find(moving.begin(), moving.end(), true) != moving.end());  // the fixture has moving cars
}

// The foreground and deletion agents estimate the scene's light once and cache it; a cache the
// current estimator did not write, or one that does not read, is estimated again, not trusted.
TEST_F(DemoScene, TheCachedLightIsReusedOnlyWhenThisEstimatorMadeItAndItReadsWhole) {
  const auto s = scene::load_scene(*dir_);
  const fs::path cache = *dir_ / "light-cache";
  const char* before = std::getenv("CHATSIM_CACHE");
  const std::string saved = before != nullptr ? before : "";
  setenv("CHATSIM_CACHE", cache.c_str(), 1);
  bool estimated = false;
  const auto first = agents::render::scene_light(s, &estimated);
  EXPECT_TRUE(estimated);
  const fs::path lj = agents::render::scene_cache_dir(s) / "light.json";
  ASSERT_TRUE(fs::exists(lj));
  EXPECT_EQ(read_json(lj)["estimator_version"].get<int>(), render::light::kLightEstimatorVersion);
  const auto again = agents::render::scene_light(s, &estimated);
  EXPECT_FALSE(estimated);
  EXPECT_TRUE(again.sky.sun_direction.isApprox(first.sky.sun_direction, 1e-6)) << again.sky.sun_direction.transpose();
  auto older = read_json(lj);
  older.erase("estimator_version");
  std::ofstream(lj) << older.dump();
  agents::render::scene_light(s, &estimated);
  EXPECT_TRUE(estimated);
  std::ofstream(lj) << "{\"sky_type\": ";  // cut short
  agents::render::scene_light(s, &estimated);
  EXPECT_TRUE(estimated);
  EXPECT_EQ(read_json(lj)["estimator_version"].get<int>(), render::light::kLightEstimatorVersion);
  if (before != nullptr) setenv("CHATSIM_CACHE", saved.c_str(), 1);
  else unsetenv("CHATSIM_CACHE");
}

// The recorded rig is wrong only by the side cameras' calibration; the trigger offsets are in
// the images' timestamps, and the scene poses each image at its own (a decimetre otherwise).
TEST_F(DemoScene, EachImageIsPosedAtItsOwnTriggerTime) {
  const auto s = scene::load_scene(*dir_);
  for (const auto& p : read("ground_truth/poses.json")["images"]) {
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    for (int k = 0; k < 16; ++k) truth.matrix()(k / 4, k % 4) = p["camera_to_world_true"][size_t(k)];
    const auto pose = s.camera_to_world(s.frames[size_t(p["frame"].get<int>())], *s.camera(p["camera"]));
    EXPECT_LT((pose.translation() - truth.translation()).norm(), 1e-3) << p.dump();
    const double deg = Eigen::AngleAxisd(truth.linear().transpose() * pose.linear()).angle() * 180 / M_PI;
    EXPECT_NEAR(deg, p["camera"] == "front" ? 0.0 : 0.3, 1e-3) << p.dump();
  }
  // Evaluation reports the same, before and after pose refinement.
  const auto r = render::gs::evaluate_nvs(quick_model(s, 10), s, {});
  ASSERT_TRUE(r.contains("pose_error")) << r.dump(1);
  const auto& left = r["pose_error"]["cameras"]["front_left"];
  EXPECT_NEAR(left["initial"]["rotation_deg"].get<double>(), 0.3, 1e-3);
  // Per axis (the same calibration error in every image): the axes make up the whole angle.
  const auto& axes = left["initial"]["rotation_xyz_deg"];
  EXPECT_NEAR(std::hypot(axes[0].get<double>(), axes[1].get<double>(), axes[2].get<double>()), 0.3, 1e-3);
  EXPECT_LT(left["initial"]["translation_m"].get<double>(), 1e-3);
  EXPECT_GT(left["count"].get<int>(), 0);
  EXPECT_TRUE(std::isfinite(left["refined"]["rotation_deg"].get<double>()));
}

TEST(DemoSceneDeterminism, SameSeedSameImages) {
  auto o = render::demo::small_demo_options(5);
  o.layout.frames = 2;
  o.layout.width = 48;
  o.layout.height = 32;
  o.clean_plates = o.truth_views = o.lidar = false;
  const fs::path a = chatsim::scratch::dir() / ("chatsim-demo-a-" + std::to_string(getpid()));
  const fs::path b = chatsim::scratch::dir() / ("chatsim-demo-b-" + std::to_string(getpid()));
  render::demo::generate_demo_scene(o, a);
  render::demo::generate_demo_scene(o, b);
  for (const char* img : {"images/front/000001.jpg", "images/front_right/000000.jpg"})
    EXPECT_EQ(cv::norm(render::read_rgb8(a / img), render::read_rgb8(b / img), cv::NORM_INF), 0) << img;
  fs::remove_all(a);
  fs::remove_all(b);
}

// Removing vehicles against the clean plates of the small preset (160x106, 8 frames): the
// ground map and exemplar fill beat diffusion inpainting inside the mask and flicker less. (At
// 96x64 and 4 frames, as in the fixture above, they do not: too few views of the ground.)
TEST(DemoSceneDeletion, BeatsDiffusionInpaintingAgainstTheCleanPlates) {
  const fs::path dir = chatsim::scratch::dir() / ("chatsim-deletion-test-" + std::to_string(getpid()));
  render::demo::generate_demo_scene(render::demo::small_demo_options(1), dir);
  const auto s = scene::load_scene(dir);
  render::inpaint::DeletionEvalOptions o;
  o.max_objects = 3;
  const auto r = render::inpaint::evaluate_deletion(s, o);
  // Without the baseline (as bench deletion's second pass): the same result, no baseline fields.
  o.baseline = false;
  const auto alone = render::inpaint::evaluate_deletion(s, o);
  fs::remove_all(dir);
  const auto& sm = r["summary"];
  ASSERT_GE(sm["objects"].get<int>(), 1);
  EXPECT_GT(sm["psnr"].get<double>(), sm["baseline_psnr"].get<double>()) << r.dump(1);
  EXPECT_LT(sm["flicker"].get<double>(), sm["baseline_flicker"].get<double>()) << r.dump(1);
  EXPECT_NEAR(alone["summary"]["psnr"].get<double>(), sm["psnr"].get<double>(), 1e-9);
  EXPECT_FALSE(alone["summary"].contains("baseline_psnr"));
  EXPECT_FALSE(alone["objects"][0].contains("baseline_flicker"));
}

// Issue #6's failure cases at once: side cameras 5 degrees off their recorded calibration and
// firing 0.1-0.15 s off their frames, exposures 2.5x apart and not recorded, vehicles moving,
// two training frames of 96x64. Training finishes, every number stays finite, and evaluation
// reports the lower quality against the same street captured without these traps.
TEST(DemoSceneHostileCapture, TrainingFinishesAndReportsTheLowerQuality) {
  auto capture = [](bool hostile, const std::string& name) {
    auto o = render::demo::small_demo_options(3);
    o.layout.frames = 4;
    o.layout.width = 96;
    o.layout.height = 64;
    o.clean_plates = o.truth_views = false;
    if (hostile) {
      o.calibration_error_deg = 5;
      o.trigger_offset_ms = {0, 150, -120};
      o.trigger_jitter_ms = 20;
      o.exposure_scale = {1.0, 2.5, 0.6};
      o.record_exposure = false;
    } else {
      o.calibration_error_deg = 0;
      o.trigger_offset_ms = {0, 0, 0};
      o.trigger_jitter_ms = 0;
      o.exposure_scale = {1.0, 1.0, 1.0};
    }
    const fs::path dir = chatsim::scratch::dir() / name;
    render::demo::generate_demo_scene(o, dir);
    return scene::load_scene(dir);
  };
  auto held_out_psnr = [](const scene::Scene& s) {
    render::gs::TrainOptions t;
    t.preset = "draft";
    t.max_iterations = 60;
    t.holdout = 2;  // trains on frames 0 and 2
    render::gs::TrainReport report;
    const auto model = render::gs::train(s, t, &report);
    EXPECT_EQ(report.iterations, 60);
    EXPECT_TRUE(std::isfinite(report.train_psnr));
    EXPECT_EQ(std::count_if(model.gaussians.p.begin(), model.gaussians.p.end(), [](float v) { return !std::isfinite(v); }), 0);
    for (const auto& [key, c] : model.camera_correction) EXPECT_TRUE(c.rotation.allFinite() && c.translation.allFinite()) << key;
    render::gs::NvsOptions n;
    n.holdout = 2;
    const auto r = render::gs::evaluate_nvs(model, s, n);
    const double psnr = r["sets"]["held_out"]["psnr"].get<double>();
    EXPECT_TRUE(std::isfinite(psnr)) << r.dump(1);
    return psnr;
  };
  const double clean = held_out_psnr(capture(false, "clean"));
  const double hostile = held_out_psnr(capture(true, "hostile"));
  EXPECT_LT(hostile, clean - 1.0) << "hostile " << hostile << " dB, clean " << clean << " dB";
}

}  // namespace
}  // namespace chatsim
