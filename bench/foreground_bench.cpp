#include "bench/foreground_bench.hpp"

#include <chrono>

#include "agents/foreground/asset_bank.hpp"
#include "render/image_io.hpp"
#include "render/image_metrics.hpp"
#include "render/path_tracer.hpp"

namespace chatsim::bench {
namespace r = chatsim::render;
using nlohmann::json;

namespace {

struct Setup {
  r::RayScene scene;
  r::Sky sky{r::SkyParams{}};
  r::EnvMap map;
  r::Lighting light;
  scene::Camera cam;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  cv::Rect region;
};

void build(Setup& s) {
  const auto model = agents::foreground::model_for({"sedan", "car", {4.6f, 1.85f, 1.45f}, {200, 30, 30}});
  std::vector<uint32_t> slots;
  for (const auto& m : model.slots) slots.push_back(s.scene.add_material(m));
  Eigen::Affine3f car = Eigen::Affine3f::Identity();
  car.rotate(Eigen::AngleAxisf(0.6f, Eigen::Vector3f::UnitZ()));
  s.scene.add_instance(s.scene.add_prototype(model.mesh, slots), car, std::nullopt, {}, r::mask::kForeground);
  const uint32_t catcher = s.scene.add_material(r::Material::shadow_catcher());
  s.scene.add_instance(s.scene.add_prototype(r::make_quad(-100, -100, 100, 100), {catcher}), Eigen::Affine3f::Identity(),
                       std::nullopt, {}, r::mask::kCatcher);
  s.scene.commit();
  s.map = s.sky.to_env_map(128, 64);
  s.light = r::Lighting::from_sky(s.sky, s.map);
  s.cam.width = 640, s.cam.height = 426;
  s.cam.fx = s.cam.fy = 320 / std::tan(25 * M_PI / 180);
  s.cam.cx = 319.5, s.cam.cy = 212.5;
  // A camera 1.6 m up, 8 m away, looking at the car: it fills about a fifth of the frame.
  const Eigen::Vector3d eye(-8, -1.5, 1.6), target(0, 0, 0.7);
  const Eigen::Vector3d z = (target - eye).normalized(), x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  s.pose.linear() << x, z.cross(x), z;
  s.pose.translation() = eye;
  s.region = cv::Rect(150, 110, 400, 230);
}

cv::Mat composite(const r::RenderedView& v) {
  // Over a flat grey road: what the compositor would do with a background.
  cv::Mat out(v.radiance.size(), CV_32FC3);
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      const float a = v.alpha.at<float>(y, x), sh = v.shadow.at<float>(y, x);
      out.at<cv::Vec3f>(y, x) = v.radiance.at<cv::Vec3f>(y, x) + cv::Vec3f(80, 80, 80) * ((1 - a) * sh);
    }
  return r::encode_srgb8(out, 0.004f);
}

}  // namespace

json run_foreground_bench(const ForegroundBenchConfig& c) {
  Setup s;
  build(s);
  r::RenderSettings rs;
  rs.include_sky = false;
  rs.max_depth = 3;
  rs.spp = c.quick ? 256 : c.reference_spp;
  rs.seed = 99;
  const auto ref = r::render_view(s.scene, s.light, s.cam, s.pose, rs, s.region);
  const cv::Mat reference = composite(ref);
  double coverage = 0;
  for (int y = 0; y < ref.alpha.rows; ++y)
    for (int x = 0; x < ref.alpha.cols; ++x) coverage += ref.alpha.at<float>(y, x);
  coverage /= double(s.cam.width * s.cam.height);
  json rows = json::array();
  for (bool denoise : {false, true})
    for (int spp : c.spp) {
      rs.spp = spp;
      rs.seed = 1;
      rs.denoise = denoise;
      const auto t0 = std::chrono::steady_clock::now();
      const auto v = r::render_view(s.scene, s.light, s.cam, s.pose, rs, s.region);
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      rows.push_back({{"spp", spp}, {"denoise", denoise}, {"seconds", secs}, {"psnr", r::psnr(composite(v), reference)}});
    }
  return {{"frame", {s.cam.width, s.cam.height}}, {"region", {s.region.width, s.region.height}}, {"vehicle_coverage", coverage},
          {"reference_spp", c.quick ? 256 : c.reference_spp}, {"runs", rows},
          {"target", "32 samples per pixel in under 2 s per frame"}};
}

}  // namespace chatsim::bench
