#include "render/demo/demo_generate.hpp"

#include <chrono>
#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"
#include "common/util/output_dir.hpp"
#include "render/equirect.hpp"
#include "render/image_io.hpp"
#include "render/sampling.hpp"

namespace chatsim::render::demo {
namespace fs = std::filesystem;
using nlohmann::json;

DemoRenderOptions small_demo_options(uint64_t seed) {
  DemoRenderOptions o;
  o.layout.seed = seed;
  o.layout.frames = 8;
  o.layout.width = 160;
  o.layout.height = 106;
  o.world.seed = seed;
  o.spp = 2;
  o.truth_spp = 4;
  o.holdout_every = 4;
  o.holdout_phase = 2;
  o.plate_every = 2;
  o.plate_min_pixels = 64;
  o.shifted_frames = {4};
  return o;
}

namespace {

json matrix_json(const Eigen::Isometry3d& m) {
  json a = json::array();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a.push_back(m.matrix()(r, c));
  return a;
}

std::string frame_name(int frame) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%06d", frame);
  return buf;
}

// Poisson-Gaussian sensor noise on linear values, then the sRGB OETF and 8 bits. The noise of
// a pixel depends only on (seed, camera, frame, pixel), so a clean plate of the same image has
// exactly the same noise.
cv::Mat expose(const cv::Mat& radiance, float exposure, double noise_scale, uint64_t seed, cv::Point origin, int full_width) {
  cv::Mat out(radiance.rows, radiance.cols, CV_8UC3);
  const float shot = float(3e-4 * noise_scale * noise_scale), read = float(4e-6 * noise_scale * noise_scale);
  for (int y = 0; y < radiance.rows; ++y)
    for (int x = 0; x < radiance.cols; ++x) {
      const cv::Vec3f r = radiance.at<cv::Vec3f>(y, x);
      Rng rng(hash_seed(seed, uint64_t((y + origin.y) * full_width + x + origin.x)));
      cv::Vec3b& o = out.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c) {
        float v = r[c] * exposure;
        if (noise_scale > 0) {
          // Box-Muller from two uniforms.
          const float u1 = std::max(rng.uniform(), 1e-7f), u2 = rng.uniform();
          const float g = std::sqrt(-2 * std::log(u1)) * std::cos(2 * kPi * u2);
          v += g * std::sqrt(shot * std::max(v, 0.0f) + read);
        }
        o[c] = uchar(std::lround(srgb_oetf(v) * 255.0f));
      }
    }
  return out;
}

// The image area an object and its shadow cover: the projected box and its shadow on the
// ground, padded. Empty when not in view; the whole image when the object reaches behind the
// camera.
cv::Rect object_region(const scene::Camera& cam, const Eigen::Isometry3d& c2w, const scene::TrackPoint& p,
                       const Eigen::Vector3d& size, const Sky& sky) {
  std::vector<Eigen::Vector3d> pts;
  for (const auto& c : scene::box_corners(p.center, size, p.yaw)) {
    pts.push_back(c);
    const Eigen::Vector3d sun = sky.sun_direction().cast<double>();
    if (sky.has_sun() && sun.z() > 0.05) pts.push_back(c - sun * (c.z() / sun.z()));
    else pts.push_back(Eigen::Vector3d(c.x(), c.y(), 0));
  }
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  int behind = 0;
  for (const auto& w : pts) {
    const Eigen::Vector3d c = c2w.inverse() * w;
    if (c.z() < 0.1) {
      ++behind;
      continue;
    }
    const double u = cam.fx * c.x() / c.z() + cam.cx, v = cam.fy * c.y() / c.z() + cam.cy;
    x0 = std::min(x0, u), x1 = std::max(x1, u), y0 = std::min(y0, v), y1 = std::max(y1, v);
  }
  const cv::Rect full(0, 0, cam.width, cam.height);
  if (behind == int(pts.size())) return {};
  if (behind > 0) return full;
  const int pad = 6;
  const cv::Rect r(int(std::floor(x0)) - pad, int(std::floor(y0)) - pad, int(std::ceil(x1 - x0)) + 2 * pad,
                   int(std::ceil(y1 - y0)) + 2 * pad);
  return r & full;
}

struct LidarSpec {
  Eigen::Vector3d mount{1.2, 0, 1.9};  // ego frame
  int beams = 32, azimuths = 1024;
  double min_elev_deg = -25, max_elev_deg = 12, max_range = 100;
};

std::vector<float> scan_lidar(const RayScene& rs, const Eigen::Isometry3d& ego, const LidarSpec& l, uint64_t seed) {
  std::vector<float> out;
  Rng rng(seed);
  const Eigen::Vector3f origin = (ego * l.mount).cast<float>();
  const Eigen::Matrix3f rot = ego.linear().cast<float>();
  for (int b = 0; b < l.beams; ++b) {
    // Denser toward the horizon, as real spinning sensors are.
    const double f = double(b) / (l.beams - 1);
    const double elev = (l.min_elev_deg + (l.max_elev_deg - l.min_elev_deg) * std::pow(f, 0.8)) * M_PI / 180;
    for (int a = 0; a < l.azimuths; ++a) {
      const double az = 2 * M_PI * a / l.azimuths;
      const Eigen::Vector3f d_ego(float(std::cos(elev) * std::cos(az)), float(std::cos(elev) * std::sin(az)), float(std::sin(elev)));
      Ray r;
      r.origin = origin;
      r.direction = rot * d_ego;
      r.t_max = float(l.max_range);
      const auto hit = rs.intersect(r);
      const float drop = rng.uniform(), noise_u1 = std::max(rng.uniform(), 1e-7f), noise_u2 = rng.uniform();
      if (!hit || drop < 0.06f) continue;
      const Material& m = rs.material(hit->material);
      if (m.specular > 0.05f && m.roughness < 0.1f && drop < 0.7f) continue;  // glass rarely returns
      const float range = hit->t + 0.02f * std::sqrt(-2 * std::log(noise_u1)) * std::cos(2 * kPi * noise_u2);
      const Eigen::Vector3f p = l.mount.cast<float>() + d_ego * range;
      const float cosine = std::abs(hit->geometric_normal.dot(r.direction));
      out.insert(out.end(), {p.x(), p.y(), p.z(), std::clamp(luminance(m.albedo) * cosine * 2.0f, 0.0f, 1.0f)});
    }
  }
  return out;
}

void write_json(const fs::path& file, const json& j) {
  std::ofstream(file) << j.dump(1) << "\n";
}

}  // namespace

DemoReport generate_demo_scene(const DemoRenderOptions& o, const fs::path& out_dir) {
  if (o.image_format != "jpg" && o.image_format != "png")
    throw std::invalid_argument("image format '" + o.image_format + "': use jpg or png");
  StagedOutputDir staged(out_dir, "scene", o.force_output);  // refused before any work
  const fs::path& tmp = staged.path();
  const auto t_start = std::chrono::steady_clock::now();
  DemoReport report;
  scene::Scene layout = scene::demo_layout(o.layout);
  const std::vector<scene::Camera> rig_true = layout.cameras;
  DemoWorld world(layout, o.world);
  fs::create_directories(tmp / "ground_truth");

  // Automatic exposure: the front camera's median radiance at frame 0 to a mid-grey.
  {
    scene::Camera small = rig_true.front();
    small.width /= 8, small.height /= 8, small.fx /= 8, small.fy /= 8, small.cx /= 8, small.cy /= 8;
    RenderSettings s;
    s.spp = 2;
    s.max_depth = 1;
    const auto v = render_view(world.scene(), world.lighting(), small, layout.ego_to_world_at(0) * small.sensor_to_ego, s);
    std::vector<float> lum;
    for (int y = 0; y < v.radiance.rows; ++y)
      for (int x = 0; x < v.radiance.cols; ++x) {
        const cv::Vec3f c = v.radiance.at<cv::Vec3f>(y, x);
        lum.push_back(luminance(Rgb(c[0], c[1], c[2])));
      }
    std::nth_element(lum.begin(), lum.begin() + long(lum.size() / 2), lum.end());
    report.exposure_s = std::clamp(0.16 / std::max(double(lum[lum.size() / 2]), 1e-6), 1e-5, 1.0);
  }

  // The recorded rig: the side cameras' extrinsics are off by a small rotation.
  Rng rig_rng(hash_seed(o.layout.seed, 77));
  for (size_t c = 1; c < layout.cameras.size(); ++c) {
    const Eigen::Vector3d axis = Eigen::Vector3d(rig_rng.uniform() - 0.5, rig_rng.uniform() - 0.5, rig_rng.uniform() - 0.5).normalized();
    layout.cameras[c].sensor_to_ego.linear() =
        layout.cameras[c].sensor_to_ego.linear() * Eigen::AngleAxisd(o.calibration_error_deg * M_PI / 180, axis).toRotationMatrix();
  }
  layout.layout_only = false;
  layout.source = "chatsim procedural demo (path traced, seed " + std::to_string(o.layout.seed) + ")";

  const int n_frames = int(layout.frames.size()), n_cams = int(rig_true.size());
  int truth_count = 0;
  for (const auto& f : layout.frames) {
    if (f.index % o.holdout_every == o.holdout_phase) truth_count += n_cams;
    if (std::find(o.shifted_frames.begin(), o.shifted_frames.end(), f.index) != o.shifted_frames.end())
      truth_count += n_cams * int(o.shifts.size());
  }
  // Progress in units of one captured image with its plates: a view costs about a third of
  // its sample ratio (seed 1, 2 cores: about 3 s per captured image at 4 samples, 16 s per view at
  // 64, 64 s at 256), so the ETA holds through the views.
  const double view_cost = std::max(1.0, double(o.truth_spp) / double(std::max(1, o.spp)) / 3);
  const double total = n_frames * n_cams + (o.truth_views ? view_cost * truth_count : 0.0) + (o.lidar ? 0.3 * n_frames : 0.0);
  double done = 0;
  auto progress = [&](const std::string& stage) {
    if (o.progress) o.progress(stage, std::min(1.0, done / total));
  };

  json poses = json::array(), plates = json::array(), views = json::array();
  Rng trigger_rng(hash_seed(o.layout.seed, 91));
  std::map<std::pair<int, int>, std::pair<double, double>> shot;  // (frame, camera) -> (time, exposure)
  for (auto& f : layout.frames) {
    for (int c = 0; c < n_cams; ++c) {
      const scene::Camera& cam = rig_true[size_t(c)];
      const double offset = (size_t(c) < o.trigger_offset_ms.size() ? o.trigger_offset_ms[size_t(c)] : 0) +
                            o.trigger_jitter_ms * (2 * trigger_rng.uniform() - 1);
      const double t = f.timestamp_s + offset / 1000.0;
      const double exposure = report.exposure_s * (size_t(c) < o.exposure_scale.size() ? o.exposure_scale[size_t(c)] : 1.0) *
                              (1 + 0.04 * (2 * trigger_rng.uniform() - 1));
      shot[{f.index, c}] = {t, exposure};
      const Eigen::Isometry3d c2w = layout.ego_to_world_at(t) * cam.sensor_to_ego;
      world.place_objects(t);
      world.commit();
      RenderSettings s;
      s.spp = o.spp;
      s.max_depth = o.max_depth;
      s.seed = hash_seed(o.layout.seed, uint64_t(f.index), uint64_t(c));
      s.clamp_indirect = float(40 * 0.18 / exposure);
      s.denoise = true;
      progress("images " + cam.name + " frame " + std::to_string(f.index));
      const auto view = render_view(world.scene(), world.lighting(), cam, c2w, s);
      const uint64_t noise_seed = hash_seed(o.layout.seed, uint64_t(f.index), uint64_t(c), 5);
      const std::string rel = "images/" + cam.name + "/" + frame_name(f.index) + "." + o.image_format;
      write_rgb8(tmp / rel, expose(view.radiance, float(exposure), o.noise_scale, noise_seed, {0, 0}, cam.width), 95);
      write_exr(tmp / "ground_truth" / "depth" / cam.name / (frame_name(f.index) + ".exr"), view.depth);
      scene::ImageRef ref;
      ref.path = rel;
      ref.timestamp_s = t;
      if (o.record_exposure) ref.exposure_s = exposure;
      f.images[cam.name] = ref;
      poses.push_back({{"camera", cam.name}, {"frame", f.index}, {"timestamp_s", t}, {"exposure_s", exposure},
                       {"camera_to_world_true", matrix_json(c2w)},
                       {"camera_to_world_recorded", matrix_json(f.ego_to_world * layout.cameras[size_t(c)].sensor_to_ego)}});
      ++report.images;
      // Clean plates: the same image without each object, over the area it and its shadow touch.
      if (o.clean_plates && f.index % o.plate_every == 0) {
        for (const auto& obj : layout.objects) {
          if (!obj.has_category_prefix("vehicle")) continue;
          const auto p = object_at_time(layout, obj, t);
          if (!p) continue;
          const cv::Rect region = object_region(cam, c2w, *p, obj.size_lwh, world.sky());
          if (region.area() < o.plate_min_pixels) continue;
          // Rendered with a margin so the smoothing sees the same neighbourhood as the full image.
          const cv::Rect padded = cv::Rect(region.x - 32, region.y - 32, region.width + 64, region.height + 64) &
                                  cv::Rect(0, 0, cam.width, cam.height);
          world.set_object_visible(obj.id, false);
          world.commit();
          const auto plate = render_view(world.scene(), world.lighting(), cam, c2w, s, padded);
          world.set_object_visible(obj.id, true);
          const cv::Rect inner(region.x - padded.x, region.y - padded.y, region.width, region.height);
          const std::string prel = "ground_truth/clean_plates/" + obj.id + "/" + cam.name + "/" + frame_name(f.index) + ".png";
          write_rgb8(tmp / prel, expose(plate.radiance(inner), float(exposure), o.noise_scale, noise_seed, region.tl(), cam.width));
          plates.push_back({{"object", obj.id}, {"camera", cam.name}, {"frame", f.index}, {"x", region.x}, {"y", region.y},
                            {"width", region.width}, {"height", region.height}, {"path", prel}});
          ++report.plates;
        }
        world.commit();
      }
      done += 1;
    }
  }

  // Ground-truth views: no sensor noise, more samples, at the true poses; clean copies of the
  // held-out frames and views shifted from some frames.
  if (o.truth_views) {
    for (const auto& f : layout.frames) {
      std::vector<ViewShift> shifts;
      if (f.index % o.holdout_every == o.holdout_phase) shifts.push_back({"none", Eigen::Vector3d::Zero()});
      if (std::find(o.shifted_frames.begin(), o.shifted_frames.end(), f.index) != o.shifted_frames.end())
        shifts.insert(shifts.end(), o.shifts.begin(), o.shifts.end());
      if (shifts.empty()) continue;
      for (int c = 0; c < n_cams; ++c) {
        const scene::Camera& cam = rig_true[size_t(c)];
        const auto [t, exposure] = shot[{f.index, c}];
        const Eigen::Isometry3d ego = layout.ego_to_world_at(t);
        world.place_objects(t);
        world.commit();
        for (const auto& sh : shifts) {
          Eigen::Isometry3d moved = ego;
          moved.translation() += ego.linear() * sh.ego_offset;
          const Eigen::Isometry3d c2w = moved * cam.sensor_to_ego;
          RenderSettings s;
          s.spp = o.truth_spp;
          s.max_depth = o.max_depth;
          s.seed = hash_seed(o.layout.seed, uint64_t(f.index), uint64_t(c), 11);
          s.clamp_indirect = float(40 * 0.18 / exposure);
          s.denoise = true;
          progress("ground truth " + cam.name + " frame " + std::to_string(f.index) + " " + sh.name);
          const auto view = render_view(world.scene(), world.lighting(), cam, c2w, s);
          const std::string name = cam.name + "_" + frame_name(f.index) + "_" + sh.name;
          write_rgb8(tmp / "ground_truth" / "views" / (name + ".png"), encode_srgb8(view.radiance, float(exposure)));
          write_exr(tmp / "ground_truth" / "views" / (name + "_depth.exr"), view.depth);
          views.push_back({{"name", name}, {"camera", cam.name}, {"frame", f.index}, {"shift", sh.name},
                           {"shift_ego_m", {sh.ego_offset.x(), sh.ego_offset.y(), sh.ego_offset.z()}},
                           {"timestamp_s", t}, {"exposure_s", exposure}, {"camera_to_world", matrix_json(c2w)},
                           {"image", "ground_truth/views/" + name + ".png"},
                           {"depth", "ground_truth/views/" + name + "_depth.exr"}});
          ++report.views;
          done += view_cost;
        }
      }
    }
  }

  if (o.lidar) {
    for (auto& f : layout.frames) {
      progress("lidar frame " + std::to_string(f.index));
      world.place_objects(f.timestamp_s);
      world.commit();
      const auto pts = scan_lidar(world.scene(), f.ego_to_world, LidarSpec{}, hash_seed(o.layout.seed, uint64_t(f.index), 3));
      const std::string rel = "lidar/" + frame_name(f.index) + ".bin";
      fs::create_directories(tmp / "lidar");
      std::ofstream(tmp / rel, std::ios::binary).write(reinterpret_cast<const char*>(pts.data()), std::streamsize(pts.size() * sizeof(float)));
      f.lidar = rel;
      ++report.lidar_frames;
      done += 0.3;
    }
  }

  // The sky, in the light estimator's format.
  const Sky& sky = world.sky();
  sky.to_env_map(512, 256, true).write_exr(tmp / "ground_truth" / "sky.exr");
  const Rgb sun = sky.sun_radiance();
  const Eigen::Vector3f sd = sky.sun_direction();
  write_json(tmp / "ground_truth" / "sky.json",
             {{"sky_type", sky.has_sun() ? "sunny" : "overcast"},
              {"sun_direction_world", {sd.x(), sd.y(), sd.z()}},
              {"sun_radiance_rgb", {sun.x(), sun.y(), sun.z()}},
              {"sun_solid_angle_sr", sun_solid_angle_sr()},
              {"turbidity", o.world.turbidity},
              {"sky_exr", "sky.exr"},
              {"sky_mapping", std::string(kEquirectMapping) + "; the disc is not in the EXR; below the horizon a diffuse ground"}});
  write_json(tmp / "ground_truth" / "poses.json", {{"images", poses}});
  write_json(tmp / "ground_truth" / "views.json", {{"views", views}});
  write_json(tmp / "ground_truth" / "clean_plates.json",
             {{"plates", plates},
              {"note", "each plate is the image without one object, cropped to where the object and its shadow were; "
                       "same exposure and the same sensor noise as the captured image"}});
  write_json(tmp / "ground_truth" / "manifest.json",
             {{"generator", "chatsim scene demo"},
              {"seed", o.layout.seed},
              {"auto_exposure_s", report.exposure_s},
              {"exposure_scale", o.exposure_scale},
              {"exposure_recorded", o.record_exposure},
              {"trigger_offset_ms", o.trigger_offset_ms},
              {"trigger_jitter_ms", o.trigger_jitter_ms},
              {"calibration_error_deg", o.calibration_error_deg},
              {"noise_scale", o.noise_scale},
              {"spp", o.spp},
              {"truth_spp", o.truth_spp},
              {"holdout", {{"every", o.holdout_every}, {"phase", o.holdout_phase}}},
              {"contents", {{"depth", "depth/<camera>/<frame>.exr: z-depth (m) of every captured image at its true pose"},
                            {"poses", "poses.json: true and recorded camera_to_world of every image"},
                            {"views", "views.json: views at true poses without sensor noise (path traced at truth_spp "
                                      "samples, denoised), unshifted on held-out frames and shifted"},
                            {"clean_plates", "clean_plates.json"},
                            {"sky", "sky.exr, sky.json"}}}});
  scene::save_scene(layout, tmp);
  staged.commit();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if (o.progress) o.progress("done", 1.0);
  return report;
}

}  // namespace chatsim::render::demo
