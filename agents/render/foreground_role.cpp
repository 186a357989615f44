#include "agents/render/foreground_role.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>

#include <opencv2/imgproc.hpp>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include "agents/core/scene_cache.hpp"
#include "agents/foreground/asset_bank.hpp"
#include "agents/render/background_role.hpp"
#include "agents/render/image_region.hpp"
#include "agents/render/render_cache.hpp"
#include "agents/render/render_job.hpp"
#include "common/scene/scene_json.hpp"
#include "render/equirect.hpp"
#include "render/gs/rasterizer.hpp"
#include "render/image_io.hpp"
#include "render/path_tracer.hpp"

namespace chatsim::agents::render {
namespace fs = std::filesystem;
using nlohmann::json;
namespace r = chatsim::render;

namespace {

// The cached estimate, when this estimator's version made it and it reads whole; otherwise
// none (and an unreadable file is named in the log), so it is made again.
std::optional<r::light::LightEstimate> cached_light(const fs::path& lj) {
  if (!fs::exists(lj)) return std::nullopt;
  try {
    const json cached = scene::read_json_file(lj);
    if (cached.value("estimator_version", 0) != r::light::kLightEstimatorVersion) return std::nullopt;
    r::light::LightEstimate est;
    est.sunny = cached.at("sky_type") == "sunny";
    for (int k = 0; k < 3; ++k) {
      est.sky.sun_direction[k] = cached.at("sun_direction_world").at(size_t(k));
      est.sun_radiance[k] = cached.at("sun_radiance_rgb").at(size_t(k));
    }
    est.sky.turbidity = cached.value("turbidity", 3.0f);
    est.sky.overcast = !est.sunny;
    est.scale = cached.value("scale", 1.0f);
    est.sun_cue = cached.value("sun_cue", "");
    return est;
  } catch (const std::exception& e) {
    spdlog::warn("{}: cannot use the cached light estimate ({}); estimating it again", lj.string(), e.what());
    return std::nullopt;
  }
}

}  // namespace

r::light::LightEstimate scene_light(const scene::Scene& s, bool* estimated) {
  if (estimated != nullptr) *estimated = false;
  static std::mutex mu;
  std::lock_guard lock(mu);
  const fs::path dir = scene_cache_dir(s);
  const fs::path lj = dir / "light.json";
  if (auto cached = cached_light(lj)) return *cached;
  const r::light::LightEstimate est = r::light::estimate_scene_light(s);
  if (estimated != nullptr) *estimated = true;
  fs::create_directories(dir);
  est.dome().write_exr(dir / "sky.exr");
  json j = est.to_json("sky.exr");
  j["scale"] = est.scale;
  j["frames"] = r::light::scene_light_frames(s);
  j["estimator_version"] = r::light::kLightEstimatorVersion;
  // Workers on other hosts may estimate at the same time: each writes its own temporary file.
  const fs::path tmp = dir / (".light.json.part" + std::to_string(getpid()));
  std::ofstream(tmp) << j.dump(1) << "\n";
  fs::rename(tmp, lj);
  return est;
}

std::optional<Eigen::Isometry3d> added_vehicle_pose(const scene::Scene& s, const json& v, double time_s) {
  const auto& traj = v.at("trajectory");
  if (!traj.is_array() || traj.empty()) return std::nullopt;
  const double t = time_s - (s.frames.empty() ? 0.0 : s.frames.front().timestamp_s);
  size_t k = 0;
  while (k + 1 < traj.size() && traj[k + 1]["t_s"].get<double>() <= t) ++k;
  const auto& a = traj[k];
  if (t > a["t_s"].get<double>() + 0.2 && k + 1 == traj.size() && traj.size() < s.frames.size()) return std::nullopt;  // left
  const auto& b = traj[std::min(k + 1, traj.size() - 1)];
  const double ta = a["t_s"], tb = b["t_s"];
  const double u = tb > ta ? std::clamp((t - ta) / (tb - ta), 0.0, 1.0) : 0.0;
  const double x = a["x"].get<double>() * (1 - u) + b["x"].get<double>() * u;
  const double y = a["y"].get<double>() * (1 - u) + b["y"].get<double>() * u;
  const double yaw = a["yaw"].get<double>() + u * std::remainder(b["yaw"].get<double>() - a["yaw"].get<double>(), 2 * M_PI);
  double z = 0;
  if (!s.lanes.empty())
    if (const auto lp = s.lanes.nearest({x, y})) {
      const auto& cl = s.lanes.lanes()[size_t(lp->lane)].centerline;
      double best = 1e18;
      for (const auto& p : cl)
        if ((p.head<2>() - Eigen::Vector2d(x, y)).norm() < best) best = (p.head<2>() - Eigen::Vector2d(x, y)).norm(), z = p.z();
    }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

namespace {

// The light at a point: what the radiance field sees around it (six 90-degree views), the sky
// dome through what it leaves open, and how much of the sun gets through.
struct LocalLight {
  r::EnvMap env;
  float sun_visibility = 1;
};

LocalLight local_light(const r::gs::RadianceField* model, const scene::Scene& s, const Eigen::Vector3d& at, double time,
                       const std::vector<std::string>& hidden, const r::EnvMap& dome, const Eigen::Vector3f& sun_dir) {
  LocalLight out;
  const int W = 64, H = 32;
  std::vector<r::Rgb> px(size_t(W * H));
  if (model == nullptr) {
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) px[size_t(y * W + x)] = dome.radiance(r::equirect_dir((x + 0.5f) / W, (y + 0.5f) / H));
    out.env = r::EnvMap(W, H, std::move(px));
    return out;
  }
  const r::gs::Gaussians g = model->placed(s, time, hidden);
  struct Face {
    Eigen::Matrix3f rot;
    cv::Mat rad, alpha;
  };
  std::vector<Face> faces;
  const Eigen::Vector3f dirs[6] = {Eigen::Vector3f::UnitX(), -Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(),
                                   -Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitZ(), -Eigen::Vector3f::UnitZ()};
  const int face_px = 24;
  for (const auto& d : dirs) {
    const Eigen::Vector3f up = std::abs(d.z()) > 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitZ();
    const Eigen::Vector3f x = d.cross(up).normalized() * -1.0f, y = d.cross(x);
    r::gs::GsView v;
    v.width = v.height = face_px;
    v.fx = v.fy = face_px / 2.0f;
    v.cx = v.cy = (face_px - 1) / 2.0f;
    v.rotation.col(0) = x, v.rotation.col(1) = y, v.rotation.col(2) = d;
    v.center = at.cast<float>();
    r::gs::Rasterizer ras;
    ras.near_m = 0.3f;
    const auto img = ras.forward(g, nullptr, v);
    faces.push_back({v.rotation, img.radiance, img.alpha});
  }
  auto lookup = [&](const Eigen::Vector3f& d, r::Rgb& rad, float& alpha) {
    int best = 0;
    float best_dot = -2;
    for (int k = 0; k < 6; ++k) {
      const float c = faces[size_t(k)].rot.col(2).dot(d);
      if (c > best_dot) best_dot = c, best = k;
    }
    const auto& f = faces[size_t(best)];
    const Eigen::Vector3f c = f.rot.transpose() * d;
    const float u = std::clamp(face_px / 2.0f * c.x() / c.z() + (face_px - 1) / 2.0f, 0.0f, float(face_px - 1));
    const float v = std::clamp(face_px / 2.0f * c.y() / c.z() + (face_px - 1) / 2.0f, 0.0f, float(face_px - 1));
    const cv::Vec3f rr = f.rad.at<cv::Vec3f>(int(v + 0.5f), int(u + 0.5f));
    rad = r::Rgb(rr[0], rr[1], rr[2]);
    alpha = f.alpha.at<float>(int(v + 0.5f), int(u + 0.5f));
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const Eigen::Vector3f d = r::equirect_dir((x + 0.5f) / W, (y + 0.5f) / H);
      r::Rgb rad;
      float a;
      lookup(d, rad, a);
      px[size_t(y * W + x)] = rad + dome.radiance(d) * (1 - a);
    }
  out.env = r::EnvMap(W, H, std::move(px));
  r::Rgb rad;
  float a;
  lookup(sun_dir.normalized(), rad, a);
  out.sun_visibility = 1 - a;
  return out;
}

// Composites the vehicles and their shadows over the background, except where the scene is
// nearer than the vehicle (or than the ground its shadow falls on).
void composite(const r::RenderedView& fg, const ViewImage& im, double ground_z, const cv::Mat& bg_depth, cv::Mat& out,
               cv::Mat& out_depth) {
  const cv::Rect region = fg.region;
  const Eigen::Matrix3d R = im.pose.linear();
  const Eigen::Vector3d C = im.pose.translation();
  for (int y = 0; y < region.height; ++y)
    for (int x = 0; x < region.width; ++x) {
      const int px = region.x + x, py = region.y + y;
      const float a = fg.alpha.at<float>(y, x);
      const float zf = fg.depth.at<float>(y, x);
      const float zb = bg_depth.empty() ? std::numeric_limits<float>::infinity() : bg_depth.at<float>(py, px);
      // Depth of the ground plane at this pixel: where a shadow would fall.
      const Eigen::Vector3d d = R * Eigen::Vector3d((px - im.cam.cx) / im.cam.fx, (py - im.cam.cy) / im.cam.fy, 1);
      const double tg = d.z() < -1e-6 ? (ground_z - C.z()) / d.z() : 1e18;
      const float zg = float(tg);  // z-depth: the ray's camera z is 1 per unit of t here
      cv::Vec3f& o = out.at<cv::Vec3f>(py, px);
      const bool scene_in_front_of_vehicle = a > 0 && zb < zf * 0.98f;
      const bool scene_in_front_of_ground = zb < zg * 0.95f;
      const float shadow = scene_in_front_of_ground ? 1.0f : fg.shadow.at<float>(y, x);
      if (scene_in_front_of_vehicle) continue;
      const cv::Vec3f f = fg.radiance.at<cv::Vec3f>(y, x);
      o = f + o * ((1 - a) * shadow);
      if (!out_depth.empty() && a > 0.5f) out_depth.at<float>(py, px) = std::min(zb, zf);
    }
}

r::AssetModel vehicle_model(const json& v) {
  static std::mutex mu;
  static std::map<std::string, r::AssetModel> cache;
  const std::string key = v.dump();
  std::lock_guard lock(mu);
  auto it = cache.find(key);
  if (it == cache.end()) {
    agents::foreground::AssetSpec spec;
    spec.asset = v.value("asset", std::string("sedan"));
    spec.type = v.value("type", std::string("car"));
    const auto size = v.value("size_lwh", std::array<double, 3>{4.5, 1.85, 1.45});
    spec.size_lwh = Eigen::Vector3f(float(size[0]), float(size[1]), float(size[2]));
    spec.color_rgb = v.value("color_rgb", std::array<int, 3>{128, 128, 128});
    it = cache.emplace(key, agents::foreground::model_for(spec)).first;
  }
  return it->second;
}

}  // namespace

AgentOutcome foreground_light(const AgentCall& call) {
  try {
    const auto s = cached_scene(call.scene);
    bool estimated = false;
    const auto light = scene_light(*s, &estimated);
    json j = light.to_json("sky.exr");
    j["estimated"] = estimated;
    return AgentOutcome::success(j);
  } catch (const scene::SceneError& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, std::string("bad scene: ") + e.what());
  }
}

AgentOutcome foreground_render(const AgentCall& call) {
  try {
    const auto s = cached_scene(call.scene);
    const RenderJob job = RenderJob::from_json(call.args);
    if (job.in.empty()) return AgentOutcome::failure(ErrorKind::BadRequest, "args.in: missing: the previous stage's folder");
    ForegroundSettings fs_settings;
    fs_settings.spp = call.args.value("spp", fs_settings.spp);
    std::shared_ptr<const r::gs::RadianceField> model;
    if (!job.model.empty()) model = load_model_cached(job.model);
    const auto light = scene_light(*s);
    const r::EnvMap dome = light.dome(128, 64);
    const auto images = view_images(*s, job, model.get());
    const auto t_start = std::chrono::steady_clock::now();
    int with_vehicles = 0;
    double render_s = 0;
    std::map<std::pair<std::string, int>, LocalLight> light_cache;  // per vehicle, every 5 frames
    for (const auto& im : images) {
      cv::Mat bg = r::read_float_image(radiance_file(job.in, im.camera, im.frame));
      const fs::path dfile = depth_file(job.in, im.camera, im.frame);
      cv::Mat bg_depth = fs::exists(dfile) ? r::read_float_image(dfile) : cv::Mat();
      const double exposure = read_exposure(job.in, im.camera, im.frame);
      // Vehicles at this time, with the shutter's span for motion blur.
      r::RayScene rs;
      std::vector<Eigen::Vector3d> centres;
      std::vector<cv::Rect> regions;  // one per vehicle with its shadow, overlapping ones merged
      double ground_z = 0;
      for (const auto& v : job.added) {
        const auto p0 = added_vehicle_pose(*s, v, im.time - exposure / 2), p1 = added_vehicle_pose(*s, v, im.time + exposure / 2);
        const auto pc = added_vehicle_pose(*s, v, im.time);
        if (!pc || !p0 || !p1) continue;
        const r::AssetModel m = vehicle_model(v);
        std::vector<uint32_t> slots;
        for (const auto& mat : m.slots) slots.push_back(rs.add_material(mat));
        rs.add_instance(rs.add_prototype(m.mesh, slots), p0->cast<float>(), p1->cast<float>(), {}, r::mask::kForeground);
        const Eigen::Vector3f size = m.size();
        centres.push_back(pc->translation() + Eigen::Vector3d(0, 0, size.z() / 2));
        ground_z = pc->translation().z();
        // Its image area: the box and its shadow on the ground.
        std::vector<Eigen::Vector3d> pts;
        const Eigen::Vector3d c = pc->translation() + Eigen::Vector3d(0, 0, size.z() / 2);
        const double yaw = std::atan2((*pc).linear()(1, 0), (*pc).linear()(0, 0));
        for (const auto& q : scene::box_corners(c, size.cast<double>(), yaw)) {
          pts.push_back(q);
          const Eigen::Vector3d sd = light.sky.sun_direction.cast<double>().normalized();
          if (light.sunny && sd.z() > 0.05) pts.push_back(q - sd * ((q.z() - ground_z) / sd.z()));
        }
        const cv::Rect rr = image_region(pts, im.cam, im.pose);
        if (rr.area() == 0) continue;
        regions.push_back(rr);
      }
      regions = merge_overlapping(std::move(regions));
      cv::Mat out = bg.clone();
      cv::Mat out_depth = bg_depth.empty() ? cv::Mat() : bg_depth.clone();
      if (!regions.empty()) {
        ++with_vehicles;
        const uint32_t catcher = rs.add_material(r::Material::shadow_catcher());
        Eigen::Affine3f ground = Eigen::Affine3f::Identity();
        ground.translate(Eigen::Vector3f(float(im.pose.translation().x()), float(im.pose.translation().y()), float(ground_z)));
        rs.add_instance(rs.add_prototype(r::make_quad(-150, -150, 150, 150), {catcher}), ground, std::nullopt, {}, r::mask::kCatcher);
        rs.commit();
        // Light where the vehicles are (the one nearest the camera stands for all).
        size_t nearest = 0;
        for (size_t k = 1; k < centres.size(); ++k)
          if ((centres[k] - im.pose.translation()).norm() < (centres[nearest] - im.pose.translation()).norm()) nearest = k;
        const std::string vid = job.added[nearest].value("id", std::to_string(nearest));
        const auto key = std::make_pair(vid, im.frame / 5);
        if (!light_cache.count(key))
          light_cache[key] = local_light(model.get(), *s, centres[nearest], im.time, job.removed, dome, light.sky.sun_direction);
        const LocalLight& ll = light_cache[key];
        r::Lighting lighting;
        lighting.sky = &ll.env;
        if (light.sunny) {
          lighting.sun_direction = light.sky.sun_direction.normalized();
          lighting.sun_radiance = light.sun_radiance * ll.sun_visibility;
          lighting.sun_cos_max = r::sun_cos_half_angle();
        }
        r::RenderSettings rset;
        rset.spp = fs_settings.spp;
        rset.max_depth = fs_settings.max_depth;
        rset.include_sky = false;
        rset.denoise = true;
        rset.shutter_open = 0, rset.shutter_close = 1;
        rset.seed = r::hash_seed(uint64_t(im.frame), std::hash<std::string>{}(im.camera));
        rset.clamp_indirect = float(50 * r::luminance(ll.env.irradiance(Eigen::Vector3f::UnitZ())) / M_PI + 1);
        rset.catcher_early_stop = 4;
        for (const cv::Rect& region : regions) {
          const auto t0 = std::chrono::steady_clock::now();
          const auto fg = r::render_view(rs, lighting, im.cam, im.pose, rset, region);
          render_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          composite(fg, im, ground_z, bg_depth, out, out_depth);
        }
      }
      r::write_exr(radiance_file(job.out, im.camera, im.frame), out, r::ExrCompression::None);
      if (!out_depth.empty()) r::write_exr(depth_file(job.out, im.camera, im.frame), out_depth);
      write_exposure(job.out, im.camera, im.frame, exposure);
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    return AgentOutcome::success({{"images", images.size()}, {"with_vehicles", with_vehicles}, {"seconds", total},
                                  {"path_tracing_seconds", render_s}, {"spp", fs_settings.spp},
                                  {"light", {{"sunny", light.sunny}, {"sun_cue", light.sun_cue}}}});
  } catch (const scene::SceneError& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, std::string("bad scene: ") + e.what());
  } catch (const std::invalid_argument& e) {
    return AgentOutcome::failure(ErrorKind::BadRequest, e.what());
  }
}

}  // namespace chatsim::agents::render
