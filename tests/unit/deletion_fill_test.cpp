// What the deletion fills with, on small synthetic scenes: the fill's level matched to the image
// around it, a removed car's path cleared in a rendered view (where the radiance field smeared
// its shadow) but not in a captured one, the field's ghosts along that path hidden with it,
// where the ground map fills, and where the field may not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <opencv2/imgproc.hpp>

#include "render/gs/model.hpp"
#include "render/inpaint/deletion.hpp"
#include "render/inpaint/seam_blend.hpp"

namespace chatsim {
namespace {
using render::inpaint::DeletionImage;

cv::Mat square_mask(cv::Size size, cv::Rect r) {
  cv::Mat m(size, CV_8U, cv::Scalar(0));
  m(r).setTo(255);
  return m;
}

TEST(SeamBlend, AFillAtTheWrongLevelTakesTheLevelAroundIt) {
  const cv::Mat original(100, 100, CV_32FC3, cv::Scalar::all(0.2));
  cv::Mat filled = original.clone();
  const cv::Mat mask = square_mask(original.size(), {30, 30, 40, 40});
  filled.setTo(cv::Scalar::all(0.3), mask);  // 1.5x too bright, as a fill from a brighter view
  EXPECT_GT(render::inpaint::harmonize_fill(filled, original, mask), 0);
  for (const cv::Point p : {cv::Point(31, 31), cv::Point(50, 50), cv::Point(68, 40)})
    EXPECT_NEAR(filled.at<cv::Vec3f>(p)[1], 0.2, 0.01) << p;
  EXPECT_FLOAT_EQ(filled.at<cv::Vec3f>(10, 10)[0], 0.2f) << "outside the mask nothing changes";
}

TEST(SeamBlend, ADifferentObjectAlongTheOutlineDoesNotBleedIntoTheFill) {
  // A bright car beside the hole: its side of the outline differs by far more than a gain.
  cv::Mat original(100, 100, CV_32FC3, cv::Scalar::all(0.2));
  original(cv::Rect(70, 20, 30, 60)).setTo(cv::Scalar::all(2.0));
  cv::Mat filled = original.clone();
  const cv::Mat mask = square_mask(original.size(), {30, 30, 40, 40});
  filled.setTo(cv::Scalar::all(0.2), mask);
  render::inpaint::harmonize_fill(filled, original, mask);
  EXPECT_NEAR(filled.at<cv::Vec3f>(50, 68)[0], 0.2, 0.01) << "next to the car";
  EXPECT_NEAR(filled.at<cv::Vec3f>(50, 50)[0], 0.2, 0.01);
}

TEST(SeamBlend, AMaskWithNothingAroundItIsLeftAlone) {
  const cv::Mat original(40, 40, CV_32FC3, cv::Scalar::all(0.2));
  cv::Mat filled(40, 40, CV_32FC3, cv::Scalar::all(0.5));
  const cv::Mat mask(40, 40, CV_8U, cv::Scalar(255));
  EXPECT_EQ(render::inpaint::harmonize_fill(filled, original, mask), 0);
  EXPECT_FLOAT_EQ(filled.at<cv::Vec3f>(20, 20)[0], 0.5f);
}

// A crossing seen by one camera 1.5 m up looking along +x (the ego stands still), a car
// crossing 12 m ahead from right to left over three frames, and a cone standing on its path.
struct Street {
  scene::Scene scene;
  scene::Camera cam;

  Street() {
    cam.name = "front";
    cam.width = 320, cam.height = 200;
    cam.fx = cam.fy = 400, cam.cx = 159.5, cam.cy = 99.5;
    Eigen::Matrix3d r;
    r << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // OpenCV camera axes in the ego's FLU frame
    cam.sensor_to_ego.linear() = r;
    cam.sensor_to_ego.translation() = Eigen::Vector3d(0, 0, 1.5);
    scene.cameras.push_back(cam);
    for (int f = 0; f < 3; ++f) {
      scene::Frame fr;
      fr.index = f, fr.timestamp_s = 0.1 * f;
      fr.images["front"].timestamp_s = fr.timestamp_s;
      scene.frames.push_back(fr);
    }
    scene::ObjectTrack car;
    car.id = "car", car.category = "vehicle.car", car.size_lwh = {4, 1.8, 1.5};
    for (int f = 0; f < 3; ++f) car.track.push_back({f, Eigen::Vector3d(12, -6 + 4 * f, 0.75), M_PI / 2});
    scene::ObjectTrack cone;
    cone.id = "cone", cone.category = "movable_object.trafficcone", cone.size_lwh = {0.5, 0.5, 0.8};
    for (int f = 0; f < 3; ++f) cone.track.push_back({f, Eigen::Vector3d(12, 3, 0.4), 0});
    scene.objects = {car, cone};
  }

  Eigen::Isometry3d pose() const { return scene.camera_to_world(scene.frames[0], cam); }

  // Where a pixel's ray meets the ground, if it looks down.
  std::optional<Eigen::Vector3d> ground_at(int x, int y) const {
    const Eigen::Vector3d d = pose().linear() * Eigen::Vector3d((x - cam.cx) / cam.fx, (y - cam.cy) / cam.fy, 1);
    if (d.z() > -1e-6) return std::nullopt;
    return pose().translation() + (-pose().translation().z() / d.z()) * d;
  }

  // A frame's image: grey road, bright sky; `ghost` darkens the road in the middle of the
  // car's path, as a field darkens where the car's shadow passed (not where the car is now).
  DeletionImage image(int frame, bool ghost, float road = 0.2f) const {
    DeletionImage im;
    im.frame = frame, im.camera = "front", im.cam = cam, im.pose = pose(), im.time = 0.1 * frame;
    im.radiance = cv::Mat(cam.height, cam.width, CV_32FC3, cv::Scalar::all(0.5));
    for (int y = 0; y < cam.height; ++y)
      for (int x = 0; x < cam.width; ++x)
        if (const auto g = ground_at(x, y)) {
          const bool dark = ghost && g->x() > 11 && g->x() < 13 && g->y() > -1 && g->y() < 1.5;
          im.radiance.at<cv::Vec3f>(y, x) = cv::Vec3f::all(dark ? 0.05f : road);
        }
    return im;
  }

  // The z-depth a field would render for frame 0: the ground, and the cone where it stands.
  cv::Mat depth(const cv::Mat& cone_pixels) const {
    cv::Mat d(cam.height, cam.width, CV_32F, cv::Scalar(std::numeric_limits<float>::infinity()));
    const Eigen::Isometry3d w2c = pose().inverse();
    for (int y = 0; y < cam.height; ++y)
      for (int x = 0; x < cam.width; ++x)
        if (const auto g = ground_at(x, y)) d.at<float>(y, x) = float((w2c * *g).z());
    d.setTo(12.0f - 0.25f, cone_pixels);
    return d;
  }
};

float mean_in(const cv::Mat& radiance, const cv::Mat& where) { return float(cv::mean(radiance, where)[1]); }

TEST(DeletionPath, ARenderedViewLosesTheGhostAlongARemovedCarsPathACapturedViewKeepsIt) {
  const Street st;
  std::vector<DeletionImage> sources;
  // The captured views: clean road, a little brighter than the field renders it.
  for (int f = 0; f < 3; ++f) sources.push_back(st.image(f, false, 0.21f));
  render::inpaint::DeletionOptions cone_only;
  cone_only.margin_m = 0, cone_only.box_pad_px = 0;
  DeletionImage rendered = st.image(0, true);
  const cv::Mat cone = render::inpaint::deletion_mask(st.scene, rendered, {"cone"}, cone_only);
  ASSERT_GT(cv::countNonZero(cone), 20);
  rendered.radiance.setTo(cv::Scalar::all(0.9), cone);
  rendered.rendered_depth = st.depth(cone);
  DeletionImage captured = rendered;
  captured.radiance = rendered.radiance.clone();
  captured.rendered_depth = cv::Mat();

  // The ghost's pixels: darkened, away from the car's outline at frame 0 and from the cone.
  const cv::Mat car_now = render::inpaint::deletion_mask(st.scene, rendered, {"car"});
  cv::Mat green;
  cv::extractChannel(rendered.radiance, green, 1);
  const cv::Mat dark = green < 0.1f;
  const cv::Mat ghost = dark & ~car_now;
  ASSERT_GT(cv::countNonZero(dark), 30);
  ASSERT_GT(cv::countNonZero(ghost), 30) << "the ghost must show beyond the car's outline for the test to mean anything";

  // Path ground the field already shows right (no ghost), away from the car's outline now.
  cv::Mat clean_path(green.size(), CV_8U, cv::Scalar(0));
  for (int y = 0; y < clean_path.rows; ++y)
    for (int x = 0; x < clean_path.cols; ++x)
      if (const auto g = st.ground_at(x, y); g && g->x() > 11.2 && g->x() < 12.8 && g->y() > -2.4 && g->y() < -1.4) clean_path.at<uchar>(y, x) = 255;
  clean_path &= ~car_now;
  ASSERT_GT(cv::countNonZero(clean_path), 30);
  const cv::Mat rendered_before = rendered.radiance.clone();

  std::vector<DeletionImage> targets{rendered, captured};
  render::inpaint::delete_objects(st.scene, {"car"}, targets, sources);
  EXPECT_NEAR(mean_in(targets[0].radiance, ghost), 0.2f, 0.02f) << "rendered: the path's ground comes from the clean views";
  EXPECT_NEAR(mean_in(targets[0].radiance, cone), 0.9f, 0.01f) << "the cone on the path stays";
  cv::Mat moved;
  cv::extractChannel(cv::abs(targets[0].radiance - rendered_before), moved, 1);
  EXPECT_EQ(cv::countNonZero((moved > 1e-6f) & clean_path), 0) << "path ground the field already shows right is left as rendered";
  EXPECT_NEAR(mean_in(targets[1].radiance, ghost), 0.05f, 0.01f) << "captured: a dark patch there is real, and stays";
}

// The deletion agent keeps the field's render behind the removed car for its depth: the
// renderer hands it over as rendered, and returns its radiance in the image's own units.
TEST(RadianceField, TheRendererBehindAVehicleHandsOverWhatItRendered) {
  const Street st;
  auto field = std::make_shared<render::gs::RadianceField>();
  field->gaussians.add({12.0f, -6.0f, 0.02f}, 1.5f, Eigen::Vector3f::Constant(0.5f), 0.95f);  // the road where the car is
  field->owner.push_back(-1);
  field->log_exposure[{0, "front"}] = float(std::log(2.0));  // the field learned this image twice as bright
  DeletionImage im = st.image(0, false);
  im.exposure = 1.0;
  int kept = 0;
  cv::Mat kept_radiance, kept_depth;
  const auto behind = render::inpaint::field_renderer(field, st.scene, {}, [&](const DeletionImage& which, const render::gs::GsImage& g) {
    ++kept;
    EXPECT_EQ(which.frame, 0);
    kept_radiance = g.radiance.clone(), kept_depth = g.depth.clone();
  });
  const auto view = behind(im, {"car"});
  const cv::Mat& out = view.radiance;
  ASSERT_EQ(kept, 1);
  ASSERT_EQ(out.size(), kept_radiance.size());
  const cv::Rect car = cv::boundingRect(render::inpaint::deletion_mask(st.scene, im, {"car"}));
  const cv::Point centre(car.x + car.width / 2, car.y + car.height - 2);  // low in the box: the road
  ASSERT_GT(kept_radiance.at<cv::Vec3f>(centre)[0], 0.0f) << "the road Gaussian is rendered there";
  EXPECT_NEAR(out.at<cv::Vec3f>(centre)[0], 2 * kept_radiance.at<cv::Vec3f>(centre)[0], 1e-5f) << "in the image's units";
  EXPECT_GT(kept_depth.at<float>(centre), 5.0f) << "its depth comes along";
  EXPECT_EQ(cv::countNonZero(kept_depth(cv::Rect(0, 0, 5, 5))), 0) << "rendered only around the mask";
  EXPECT_EQ(cv::norm(view.depth, kept_depth, cv::NORM_INF), 0.0) << "and the deletion gets it too";
}

TEST(RadianceField, ImagesInTheFieldsUnitsKeepTheirPixels) {
  const Street st;
  render::gs::RadianceField field;
  field.log_exposure[{0, "front"}] = float(std::log(2.0));
  DeletionImage im = st.image(0, false);
  im.exposure = 0.5;
  const auto out = render::inpaint::in_field_units({im}, st.scene, field);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_DOUBLE_EQ(out[0].exposure, field.exposure(st.scene, 0, "front"));
  EXPECT_NE(out[0].exposure, im.exposure) << "the test needs a field that learned another exposure";
  const cv::Mat pixels = out[0].radiance * out[0].exposure - im.radiance * im.exposure;
  EXPECT_LT(cv::norm(pixels, cv::NORM_INF), 1e-6) << "radiance x exposure (the pixel) is unchanged";
  EXPECT_LT(cv::norm(im.radiance - st.image(0, false).radiance, cv::NORM_INF), 1e-9) << "the input images are left alone";
}

TEST(RadianceField, HidingAnObjectAlsoDropsWhatTheBackgroundLearnedAlongItsPath) {
  const Street st;
  render::gs::RadianceField field;
  const auto add = [&](Eigen::Vector3f p) {
    field.gaussians.add(p, 0.1f, Eigen::Vector3f::Zero(), 0.9f);
    field.owner.push_back(-1);
  };
  add({12.3f, 0.5f, 0.8f});   // inside the space the car crossed, between labelled frames
  add({12.0f, 0.5f, 0.02f});  // the road under it
  add({5.0f, 0.5f, 0.8f});    // in front of the crossing
  EXPECT_EQ(field.placed(st.scene, 0.0).size(), 3u);
  const auto hidden = field.placed(st.scene, 0.0, {"car"});
  ASSERT_EQ(hidden.size(), 2u);
  EXPECT_FLOAT_EQ(hidden.at(0)[render::gs::kPosZ], 0.02f);
  EXPECT_FLOAT_EQ(hidden.at(1)[render::gs::kPosX], 5.0f);
  // Placed into a buffer that held more (as training reuses one), the same and no more.
  render::gs::Gaussians reused = field.placed(st.scene, 0.0);
  std::vector<int> source{7, 7, 7, 7};
  field.place(st.scene, 0.0, {"car"}, reused, &source);
  EXPECT_EQ(reused.p, hidden.p);
  EXPECT_EQ(source, (std::vector<int>{1, 2}));
}

// Where a ray meets the ground at a grazing angle, the ground map does not fill it (a few
// centimetres of ground height move the point metres away): 2D inpainting does. A cone 30 m
// ahead of a camera 1.5 m up is seen 2.9 deg down; 9 m ahead, 9.5 deg.
TEST(DeletionFallback, TheGroundMapFillsOnlyWhereRaysMeetTheGroundSteeply) {
  const auto fallback_share = [](double cone_x, double min_depression_deg = render::inpaint::DeletionOptions{}.min_ground_depression_deg) {
    Street st;
    for (auto& p : st.scene.objects[1].track) p.center.x() = cone_x;
    std::vector<DeletionImage> sources;
    for (int f = 0; f < 3; ++f) sources.push_back(st.image(f, false));
    std::vector<DeletionImage> target{st.image(0, false)};
    const int masked = cv::countNonZero(render::inpaint::deletion_mask(st.scene, target[0], {"cone"}));
    render::inpaint::DeletionOptions o;
    o.min_ground_depression_deg = min_depression_deg;
    const auto stats = render::inpaint::delete_objects(st.scene, {"cone"}, target, sources, o);
    EXPECT_GT(masked, 0);
    return double(stats.fallback_pixels) / std::max(masked, 1);
  };
  EXPECT_DOUBLE_EQ(fallback_share(30), 1.0) << "far: none of it from the ground map";
  EXPECT_LT(fallback_share(30, 0.0), 0.9) << "without the limit the map would fill its lower part";
  EXPECT_LT(fallback_share(9), 0.7) << "near: its lower part from the ground map";
}

// The field fills behind an object unless what it renders there lies in front of the object's
// box: a field that learned a parked car a few metres before its box (a sparse capture does not
// pin the depth) still shows the car, darkly blurred, after the box's Gaussians are dropped. Then
// 2D inpainting fills.
TEST(DeletionFallback, TheFieldDoesNotFillWithSomethingBeforeTheRemovedBox) {
  Street st;
  for (auto& p : st.scene.objects[0].track) p.center = {30, -3, 0.75};  // parked 30 m ahead: no ground-map fill
  std::vector<DeletionImage> sources;
  for (int f = 0; f < 3; ++f) sources.push_back(st.image(f, false));
  const cv::Mat car = render::inpaint::deletion_mask(st.scene, sources[0], {"car"});
  const auto run = [&](float depth_over_car, double max_in_front_share) {
    std::vector<DeletionImage> target{st.image(0, false)};
    render::inpaint::DeletionOptions o;
    o.max_field_in_front_share = max_in_front_share;
    cv::Mat depth = st.depth(cv::Mat(st.cam.height, st.cam.width, CV_8U, cv::Scalar(0)));  // the ground behind
    if (depth_over_car > 0) depth.setTo(depth_over_car, car);
    const render::inpaint::BackgroundRenderer field = [&](const DeletionImage& im, const std::vector<std::string>&) {
      return render::inpaint::BackgroundView{im.radiance.clone(), depth};
    };
    return render::inpaint::delete_objects(st.scene, {"car"}, target, sources, o, field);
  };
  const auto behind = run(0, 0.5), before = run(26, 0.5), unchecked = run(26, 1);
  EXPECT_GT(behind.fallback_pixels, 0);
  EXPECT_EQ(behind.field_fills, 1) << "the ground behind the car";
  EXPECT_EQ(before.field_fills, 0) << "a surface 26 m away, before the box (its near side is 29 m away)";
  EXPECT_EQ(before.field_rejected, 1);
  EXPECT_EQ(unchecked.field_fills, 1) << "with the check off, the field always fills";
}

}  // namespace
}  // namespace chatsim
