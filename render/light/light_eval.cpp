#include "render/light/light_eval.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"
#include "render/color.hpp"
#include "render/equirect.hpp"
#include "render/image_io.hpp"
#include "render/light/light_estimate.hpp"
#include "render/sampling.hpp"

namespace chatsim::render::light {
namespace {

constexpr double kCapDeg = 5, kRingDeg = 10;

// The angle between two unit directions, in degrees.
double angle_deg(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  return std::acos(std::clamp(double(a.dot(b)), -1.0, 1.0)) * 180 / M_PI;
}

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();  // null in the JSON: nothing measured
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

double cap_excess(const std::function<float(const Eigen::Vector3f&)>& lum, const Eigen::Vector3f& peak) {
  // Numerical integral over the 10-degree disc around the peak on a polar grid.
  const Frame f(peak);
  std::vector<float> ring;
  double cap = 0;
  const int nr = 40, nphi = 64;
  std::vector<std::pair<float, double>> cap_samples;
  for (int i = 0; i < nr; ++i) {
    const double theta = (i + 0.5) / nr * kRingDeg * M_PI / 180;
    const double d_omega = std::sin(theta) * (kRingDeg * M_PI / 180 / nr) * (2 * M_PI / nphi);
    for (int k = 0; k < nphi; ++k) {
      const double phi = 2 * M_PI * (k + 0.5) / nphi;
      const Eigen::Vector3f d = f.to_world(Eigen::Vector3f(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                                                           float(std::cos(theta))));
      const float l = lum(d);
      if (theta < kCapDeg * M_PI / 180) cap_samples.emplace_back(l, d_omega);
      else ring.push_back(l);
    }
  }
  std::nth_element(ring.begin(), ring.begin() + long(ring.size() / 2), ring.end());
  const double level = ring[ring.size() / 2];
  for (const auto& [l, w] : cap_samples) cap += std::max(0.0, double(l) - level) * w;
  return cap;
}

}  // namespace

PanoramaPeak panorama_peak(const EnvMap& pano) {
  cv::Mat lum(pano.height(), pano.width(), CV_32F);
  for (int y = 0; y < pano.height(); ++y)
    for (int x = 0; x < pano.width(); ++x) lum.at<float>(y, x) = luminance(pano.at(x, y));
  cv::GaussianBlur(lum, lum, cv::Size(0, 0), 1.5);
  cv::Point at;
  cv::minMaxLoc(lum, nullptr, nullptr, nullptr, &at);
  PanoramaPeak p;
  p.direction = equirect_dir((at.x + 0.5f) / float(pano.width()), (at.y + 0.5f) / float(pano.height()));
  p.irradiance = cap_excess([&](const Eigen::Vector3f& d) { return luminance(pano.radiance(d)); }, p.direction);
  return p;
}

double overbright_ground_share(const EnvMap& pano) {
  // Row y's pixels span the same solid angle; row 0 is at the zenith.
  const auto row_sr = [](int y, int w, int h) { return std::sin((y + 0.5) * M_PI / h) * (M_PI / h) * (2 * M_PI / w); };
  // The most any plane receives, max over n of the integral of L (n . d)+: over a coarse copy of
  // the map that keeps each block's power, with the coarse directions as the normals.
  const int cw = 64, ch = 32;
  std::vector<double> power(size_t(cw * ch), 0.0);
  for (int y = 0; y < pano.height(); ++y)
    for (int x = 0; x < pano.width(); ++x)
      power[size_t((y * ch / pano.height()) * cw + x * cw / pano.width())] += luminance(pano.at(x, y)) * row_sr(y, pano.width(), pano.height());
  std::vector<Eigen::Vector3f> dirs;
  for (int y = 0; y < ch; ++y)
    for (int x = 0; x < cw; ++x) dirs.push_back(equirect_dir((x + 0.5f) / cw, (y + 0.5f) / ch));
  double max_irradiance = 0;
  for (const auto& n : dirs) {
    double e = 0;
    for (size_t k = 0; k < dirs.size(); ++k) e += power[k] * std::max(0.0f, n.dot(dirs[k]));
    max_irradiance = std::max(max_irradiance, e);
  }
  const double bound = max_irradiance / M_PI;  // a white diffuse surface facing the brightest way
  double over = 0;
  for (int y = pano.height() / 2; y < pano.height(); ++y)
    for (int x = 0; x < pano.width(); ++x)
      if (luminance(pano.at(x, y)) > bound) over += row_sr(y, pano.width(), pano.height());
  return over / (4 * M_PI);
}

nlohmann::json evaluate_on_panorama(const EnvMap& pano, const std::string& name, int headings, int width, const std::string& save_dir) {
  const PanoramaPeak truth = panorama_peak(pano);
  const double overbright = overbright_ground_share(pano);
  nlohmann::json results = nlohmann::json::array();
  std::vector<double> angles, logs, seconds;
  int sunny = 0;
  for (int h = 0; h < headings; ++h) {
    const double heading = 2 * M_PI * h / headings;
    std::vector<LightView> views;
    // Auto exposure over the three crops: the median radiance to a mid-grey, as a camera would.
    std::vector<float> lum_all;
    std::vector<cv::Mat> radiance;
    for (double yaw_deg : {0.0, 40.0, -40.0}) {
      LightView v;
      v.camera.name = "cam";
      v.camera.width = width;
      v.camera.height = width * 2 / 3;
      v.camera.fx = v.camera.fy = width / 2.0 / std::tan(25 * M_PI / 180);
      v.camera.cx = (width - 1) / 2.0;
      v.camera.cy = (v.camera.height - 1) / 2.0;
      const double yaw = heading + yaw_deg * M_PI / 180;
      Eigen::Matrix3d cv_in_flu;
      cv_in_flu << 0, 0, 1, -1, 0, 0, 0, -1, 0;
      v.camera_to_world = Eigen::Isometry3d::Identity();
      v.camera_to_world.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * cv_in_flu;
      v.camera_to_world.translation() = Eigen::Vector3d(0, 0, 1.6);
      cv::Mat rad(v.camera.height, v.camera.width, CV_32FC3);
      for (int y = 0; y < rad.rows; ++y)
        for (int x = 0; x < rad.cols; ++x) {
          const Eigen::Vector3d d = v.camera_to_world.linear() * Eigen::Vector3d((x - v.camera.cx) / v.camera.fx, (y - v.camera.cy) / v.camera.fy, 1);
          const Rgb c = pano.radiance(d.normalized().cast<float>());
          rad.at<cv::Vec3f>(y, x) = {c.x(), c.y(), c.z()};
          if ((x + y) % 7 == 0) lum_all.push_back(luminance(c));
        }
      radiance.push_back(rad);
      views.push_back(v);
    }
    std::nth_element(lum_all.begin(), lum_all.begin() + long(lum_all.size() / 2), lum_all.end());
    const double exposure = 0.15 / std::max(double(lum_all[lum_all.size() / 2]), 1e-9);
    for (size_t k = 0; k < views.size(); ++k) {
      cv::Mat rgb(radiance[k].rows, radiance[k].cols, CV_8UC3);
      for (int y = 0; y < rgb.rows; ++y)
        for (int x = 0; x < rgb.cols; ++x)
          for (int c = 0; c < 3; ++c)
            rgb.at<cv::Vec3b>(y, x)[c] = uchar(std::lround(srgb_oetf(float(radiance[k].at<cv::Vec3f>(y, x)[c] * exposure)) * 255));
      views[k].rgb = rgb;
      views[k].exposure = exposure;
    }
    if (!save_dir.empty()) {
      // Left, front, right side by side, as the driver would see them.
      cv::Mat strip;
      cv::hconcat(std::vector<cv::Mat>{views[1].rgb, views[0].rgb, views[2].rgb}, strip);
      std::filesystem::create_directories(save_dir);
      char file[32];
      std::snprintf(file, sizeof file, "-%03d.png", int(std::lround(heading * 180 / M_PI)));
      write_rgb8(std::filesystem::path(save_dir) / (std::filesystem::path(name).stem().string() + file), strip);
    }
    // Whether the panorama's sun lies inside one of the crops: out of them, only the sky's
    // gradient and the scene's shading can tell where it is.
    bool in_view = false;
    for (const auto& v : views) {
      const auto p = scene::project(v.camera, v.camera_to_world, v.camera_to_world.translation() + 1e3 * truth.direction.cast<double>());
      in_view |= p && p->in_image;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const LightEstimate est = estimate_light(views);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Eigen::Vector3f dir;
    double intensity;
    if (est.sunny) {
      dir = est.sky.sun_direction.normalized();
      intensity = luminance(est.sun_radiance) * sun_solid_angle_sr();
    } else {
      const EnvMap dome = est.dome(256, 128);
      dir = panorama_peak(dome).direction;
      intensity = panorama_peak(dome).irradiance;
    }
    const double angle = angle_deg(dir, truth.direction);
    // The sky's own say: how well it fits with the true sun against its best direction.
    const SkyFitProbe probe = probe_clear_sky(views, truth.direction);
    const auto or_null = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
    // Worse by more than 1 %: the true sun is the panorama's brightest pixel, 0.7 deg wide, so
    // a grid direction may fit a hair better than it.
    constexpr double kWorseFitMargin = 0.01;
    const bool worse = probe.rms_at && probe.rms_best && *probe.rms_at > *probe.rms_best + kWorseFitMargin;
    const nlohmann::json sky_alone{{"rms_log_error_at_true_sun", or_null(probe.rms_at)},
                                   {"rms_log_error_at_best", or_null(probe.rms_best)},
                                   {"true_sun_fits_worse", worse},
                                   {"best_angular_error_deg", angle_deg(probe.best_direction, truth.direction)}};
    const double log_ratio = std::log10(std::max(intensity, 1e-12) / std::max(truth.irradiance, 1e-12)), log_err = std::abs(log_ratio);
    angles.push_back(angle), logs.push_back(log_err), seconds.push_back(secs);
    sunny += est.sunny ? 1 : 0;
    results.push_back({{"heading_deg", heading * 180 / M_PI}, {"sun_in_view", in_view}, {"sky_type", est.sunny ? "sunny" : "overcast"},
                       {"sun_cue", est.sun_cue}, {"peak_angular_error_deg", angle}, {"log10_intensity_error", log_err},
                       {"log10_intensity_ratio", log_ratio},  // signed: above 0, the estimate is too bright
                       {"estimated_direction", {dir.x(), dir.y(), dir.z()}},
                       {"sky_alone", sky_alone},
                       {"seconds", secs}});
  }
  return {{"panorama", name},
          {"peak_direction", {truth.direction.x(), truth.direction.y(), truth.direction.z()}},
          {"peak_elevation_deg", std::asin(std::clamp(double(truth.direction.z()), -1.0, 1.0)) * 180 / M_PI},
          {"peak_irradiance", truth.irradiance},
          // A clipped sun's irradiance is a lower bound: its intensity errors say little.
          {"peak_clipped", overbright > kClippedSunGroundShare},
          {"overbright_ground_share", overbright},
          {"median_angular_error_deg", median(angles)},
          {"median_log10_intensity_error", median(logs)},
          {"median_seconds", median(seconds)},
          {"estimated_sunny", sunny},
          {"headings", results}};
}

nlohmann::json evaluate_panoramas(const std::vector<std::string>& files, int headings, int width, const std::string& save_dir,
                                  const std::function<void(const std::string&)>& progress) {
  nlohmann::json all = nlohmann::json::array();
  std::vector<double> angles, logs, logs_with_clipped, baseline;
  std::vector<double> group_angles[2], group_seconds[2];  // the sun in a crop, out of them
  std::vector<double> group_sky_alone[2];                  // the sky fit's best direction's error
  int truth_fits_worse[2] = {0, 0};                        // headings whose sky fits the true sun worse
  std::vector<std::string> clipped;
  for (const auto& file : files) {
    const auto pano = EnvMap::read(file);
    const nlohmann::json r = evaluate_on_panorama(pano, std::filesystem::path(file).filename().string(), headings, width, save_dir);
    const Eigen::Vector3f peak(r["peak_direction"][0].get<float>(), r["peak_direction"][1].get<float>(), r["peak_direction"][2].get<float>());
    for (const auto& h : r["headings"]) {
      angles.push_back(h["peak_angular_error_deg"]);
      const int group = h["sun_in_view"].get<bool>() ? 0 : 1;
      group_angles[group].push_back(h["peak_angular_error_deg"]);
      group_seconds[group].push_back(h["seconds"]);
      const auto& sky = h["sky_alone"];
      group_sky_alone[group].push_back(sky["best_angular_error_deg"]);
      if (sky["true_sun_fits_worse"].get<bool>()) ++truth_fits_worse[group];
      logs_with_clipped.push_back(h["log10_intensity_error"]);
      if (!r["peak_clipped"].get<bool>()) logs.push_back(h["log10_intensity_error"]);
      const double heading = h["heading_deg"].get<double>() * M_PI / 180;
      const Eigen::Vector3f guess(float(std::cos(heading) * 0.707), float(std::sin(heading) * 0.707), 0.707f);
      baseline.push_back(angle_deg(guess, peak));
    }
    if (progress) {
      char line[320];
      std::snprintf(line, sizeof line, "%s: median peak error %.1f deg, median log10 intensity error %.2f%s", r["panorama"].get<std::string>().c_str(),
                    r["median_angular_error_deg"].get<double>(), r["median_log10_intensity_error"].get<double>(),
                    r["peak_clipped"].get<bool>() ? " (its sun is clipped: intensity not counted in the median)" : "");
      progress(line);
    }
    if (r["peak_clipped"].get<bool>()) clipped.push_back(r["panorama"]);
    all.push_back(r);
  }
  return {{"panoramas", all},
          {"median_angular_error_deg", median(angles)},
          {"median_log10_intensity_error", median(logs)},
          {"median_log10_intensity_error_with_clipped", median(logs_with_clipped)},
          {"clipped_sun_panoramas", clipped},
          {"sun_in_view", {{"headings", group_angles[0].size()}, {"median_angular_error_deg", median(group_angles[0])},
                           {"median_seconds", median(group_seconds[0])}, {"sky_alone_median_angular_error_deg", median(group_sky_alone[0])},
                           {"sky_fits_true_sun_worse", truth_fits_worse[0]}}},
          {"sun_out_of_view", {{"headings", group_angles[1].size()}, {"median_angular_error_deg", median(group_angles[1])},
                               {"median_seconds", median(group_seconds[1])}, {"sky_alone_median_angular_error_deg", median(group_sky_alone[1])},
                               {"sky_fits_true_sun_worse", truth_fits_worse[1]}}},
          {"baseline_fixed_guess_median_angular_error_deg", median(baseline)},
          {"targets", {{"median_angular_error_deg", 15}, {"median_log10_intensity_error", 0.25}}}};
}

nlohmann::json evaluate_on_scene(const scene::Scene& s, int every, const std::function<void(const std::string&)>& progress, int clip_frames) {
  const auto truth_file = s.dir / "ground_truth" / "sky.json";
  std::ifstream in(truth_file);
  if (!in) throw std::invalid_argument(truth_file.string() + ": no ground-truth sky (only a generated demo scene has one: chatsim scene demo)");
  nlohmann::json truth;
  try {
    truth = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(truth_file.string() + ": not valid JSON (" + e.what() + ")");
  }
  if (!truth.contains("sun_direction_world") || !truth.contains("sun_radiance_rgb"))
    throw std::invalid_argument(truth_file.string() + ": needs sun_direction_world and sun_radiance_rgb");
  const auto& td = truth["sun_direction_world"];
  const auto& tr = truth["sun_radiance_rgb"];
  const Eigen::Vector3f sun = Eigen::Vector3f(td[0].get<float>(), td[1].get<float>(), td[2].get<float>()).normalized();
  const double sun_lum = luminance(Rgb(tr[0].get<float>(), tr[1].get<float>(), tr[2].get<float>()));
  nlohmann::json frames = nlohmann::json::array();
  std::vector<double> angles, logs, seconds;
  for (const auto& f : s.frames) {
    if (f.index % std::max(1, every) != 0) continue;
    const auto views = scene_light_views(s, f.index);
    if (views.empty()) continue;
    const auto t0 = std::chrono::steady_clock::now();
    const LightEstimate est = estimate_light(views, scene_ground_boxes(s, f.index));
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Eigen::Vector3f found = est.sky.sun_direction.normalized();
    const double angle = angle_deg(found, sun);
    const double log_err = std::abs(std::log10(std::max(double(luminance(est.sun_radiance)), 1e-12) / std::max(sun_lum, 1e-12)));
    angles.push_back(angle), logs.push_back(log_err), seconds.push_back(secs);
    frames.push_back({{"frame", f.index}, {"sky_type", est.sunny ? "sunny" : "overcast"}, {"sun_cue", est.sun_cue},
                      {"peak_angular_error_deg", angle}, {"log10_intensity_error", log_err},
                      {"estimated_direction", {found.x(), found.y(), found.z()}}, {"seconds", secs}});
    if (progress) {
      char line[160];
      std::snprintf(line, sizeof line, "frame %d: sun %.1f deg off (%s), %.1f s", f.index, angle, est.sun_cue.c_str(), secs);
      progress(line);
    }
  }
  if (angles.empty()) throw std::invalid_argument(s.dir.string() + ": no frame with images to estimate from");
  // What the agents use: one estimate from frames spread over the clip.
  const auto t0 = std::chrono::steady_clock::now();
  const LightEstimate clip = estimate_scene_light(s, clip_frames);
  const double clip_secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Eigen::Vector3f clip_found = clip.sky.sun_direction.normalized();
  const double clip_angle = angle_deg(clip_found, sun);
  const double clip_log = std::abs(std::log10(std::max(double(luminance(clip.sun_radiance)), 1e-12) / std::max(sun_lum, 1e-12)));
  if (progress) {
    char line[200];
    std::snprintf(line, sizeof line, "clip of %d frames: sun %.1f deg off (%s), log10 intensity error %.2f, %.1f s", clip_frames, clip_angle,
                  clip.sun_cue.c_str(), clip_log, clip_secs);
    progress(line);
  }
  return {{"scene", s.name},
          {"sun_direction", {sun.x(), sun.y(), sun.z()}},
          {"median_angular_error_deg", median(angles)},
          {"median_log10_intensity_error", median(logs)},
          {"median_seconds", median(seconds)},
          {"frames", frames},
          {"clip",
           {{"frames", scene_light_frames(s, clip_frames)},
            {"sky_type", clip.sunny ? "sunny" : "overcast"},
            {"sun_cue", clip.sun_cue},
            {"peak_angular_error_deg", clip_angle},
            {"estimated_direction", {clip_found.x(), clip_found.y(), clip_found.z()}},
            {"log10_intensity_error", clip_log},
            {"seconds", clip_secs}}}};
}

}  // namespace chatsim::render::light
