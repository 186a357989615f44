#include "render/gs/trainer.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <unordered_map>

#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"
#include "render/color.hpp"
#include "render/gs/moving_mask.hpp"
#include "render/gs/ssim_loss.hpp"
#include "render/gs/trainer_parts.hpp"
#include "render/image_io.hpp"
#include "render/parallel.hpp"
#include "common/util/preset_names.hpp"

namespace chatsim::render::gs {
namespace {

struct Preset {
  int iterations, max_width;
  size_t max_gaussians;
};
Preset preset(const std::string& name) {
  if (name == "quality") return {6000, 960, 1500000};
  if (name == "draft") return {500, 480, 150000};
  // fast: 1800 iterations took 475-478 s on the demo scene on 2 cores (the budget is 600 s; 1500
  // took 430 s after the rasteriser walked only the rows' spans of each footprint, 428-481 s
  // before it, on days the machine ran at different speeds).
  if (name == "fast") return {1800, 640, 600000};
  throw std::invalid_argument("unknown preset '" + name + "' (use " + std::string(kPresetChoices) + ")");
}


}  // namespace

using namespace detail;

RadianceField train(const scene::Scene& s, const TrainOptions& o, TrainReport* report_out) {
  const auto t0 = std::chrono::steady_clock::now();
  const Preset pr = preset(o.preset);
  const int iterations = o.max_iterations > 0 ? o.max_iterations : pr.iterations;
  const int max_width = o.max_width > 0 ? o.max_width : pr.max_width;
  const size_t max_gaussians = o.max_gaussians > 0 ? o.max_gaussians : pr.max_gaussians;
  if (s.layout_only) throw std::invalid_argument(s.dir.string() + ": a layout-only scene has no images to train on");
  TrainReport report;
  std::vector<TrainImage> images = load_images(s, o, max_width, &report.held_out);
  if (images.empty()) throw std::invalid_argument(s.dir.string() + ": no images to train on");
  report.images = int(images.size());
  if (o.depth_weight > 0) attach_lidar(s, images, o.seed);
  report.width = images.front().cam.width;
  report.height = images.front().cam.height;

  RadianceField model;
  model.use_exposure = o.exposure;
  for (const auto& obj : s.objects) model.objects.push_back(obj.id);
  // Scene scale: the spread of the camera centres.
  std::vector<Eigen::Vector3d> path;
  for (const auto& im : images) path.push_back(im.pose.translation());
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : path) centroid += p;
  centroid /= double(path.size());
  double extent = 0;
  for (const auto& p : path) extent = std::max(extent, (p - centroid).norm());
  extent = std::max(5.0, 1.1 * extent);
  // Median image radiance: the start for colours nobody saw and the sky.
  std::vector<float> lum;
  for (const auto& im : images)
    for (int y = 0; y < im.rgb.rows; y += 7)
      for (int x = 0; x < im.rgb.cols; x += 7) lum.push_back(srgb_to_linear_table()[im.rgb.at<cv::Vec3b>(y, x)[1]] / float(im.exposure));
  std::nth_element(lum.begin(), lum.begin() + long(lum.size() / 2), lum.end());
  const float median_log = std::log(std::max(lum[lum.size() / 2], 1e-6f));
  float sky_log = median_log;
  {
    std::vector<float> top;
    for (const auto& im : images)
      for (int x = 0; x < im.rgb.cols; x += 5) top.push_back(srgb_to_linear_table()[im.rgb.at<cv::Vec3b>(0, x)[2]] / float(im.exposure));
    std::nth_element(top.begin(), top.begin() + long(top.size() / 2), top.end());
    sky_log = std::log(std::max(top[top.size() / 2], 1e-6f));
  }
  model.sky = SkyTexture(128, 64, sky_log);

  // Seeds: LiDAR (background and objects), facades above it; random points when there is no LiDAR.
  std::vector<Seed> seeds = lidar_seeds(s, path);
  const auto facades = facade_seeds(s, images);
  seeds.insert(seeds.end(), facades.begin(), facades.end());
  assign_seeds_to_objects(s, seeds);
  std::mt19937_64 rng(o.seed);
  if (seeds.empty()) {
    std::uniform_real_distribution<double> u(-1, 1);
    for (int k = 0; k < 50000; ++k) {
      const auto& im = images[size_t(rng() % images.size())];
      const Eigen::Vector2d px((u(rng) * 0.5 + 0.5) * im.cam.width, (u(rng) * 0.5 + 0.5) * im.cam.height);
      const double d = 2 + 40 * (u(rng) * 0.5 + 0.5);
      const Eigen::Vector3d w = scene::unproject(im.cam, im.pose, px, d);
      seeds.push_back({w.cast<float>(), float(d * 8 / im.cam.fx), -1, im.frame, w.cast<float>()});
    }
  }
  if (seeds.size() > max_gaussians / 2) {
    std::shuffle(seeds.begin(), seeds.end(), rng);
    seeds.resize(max_gaussians / 2);
  }
  for (const auto& sd : seeds) {
    model.gaussians.add(sd.position, sd.sigma, seed_colour(images, sd, median_log), 0.3f);
    model.owner.push_back(sd.owner);
  }

  // Optimiser state.
  Adam adam, sky_adam;
  adam.resize(model.gaussians.p.size());
  sky_adam.resize(model.sky.data().size());
  std::map<std::string, TwistParam> cam_twist;
  std::map<ImageKey, TwistParam> img_twist;
  std::map<ImageKey, std::array<float, 3>> exp_state;  // value, m, v
  for (const auto& im : images) {
    model.log_exposure[{im.frame, im.camera}] = 0;
    exp_state[{im.frame, im.camera}] = {0, 0, 0};
  }
  if (o.pose_refinement) {
    for (const auto& c : s.cameras) {
      model.camera_correction[c.name] = PoseCorrection{};
      cam_twist[c.name] = TwistParam{};
    }
    for (const auto& im : images) {
      model.image_correction[{im.frame, im.camera}] = PoseCorrection{};
      img_twist[{im.frame, im.camera}] = TwistParam{};
    }
    for (auto& [k, t] : cam_twist) t.target = &model.camera_correction[k];
    for (auto& [k, t] : img_twist) t.target = &model.image_correction[k];
  }
  const bool learn_exposure = o.exposure;
  std::vector<float> screen_accum(model.gaussians.size(), 0.0f), denom(model.gaussians.size(), 0.0f);
  const auto parked = static_boxes(s);
  const std::vector<bool> moving = moving_objects(s);

  Rasterizer raster;
  raster.threads = o.threads;
  std::vector<size_t> order(images.size());
  std::iota(order.begin(), order.end(), 0);
  size_t next = order.size();
  double loss_ema = 0;
  std::vector<double> recent_psnr;  // the last 100 iterations'
  std::vector<double> window_losses;
  // CHATSIM_DEBUG_TRAIN: print the spread of the screen-space gradients at each densification.
  const bool debug_densify = std::getenv("CHATSIM_DEBUG_TRAIN") != nullptr;
  const int densify_from = iterations / 10, densify_until = iterations * 6 / 10, densify_every = std::max(50, iterations / 20);
  // Per-iteration buffers, kept between iterations: allocated afresh, their tens of MB came as
  // fresh pages each time. With these and the rasteriser's kept, 1000 iterations on the demo
  // scene took 322 s instead of 546.
  Gaussians placed;
  std::vector<int> source;
  GsGrads grads;
  std::vector<float> param_grads;  // the model's (objects' in their frames)
  SsimLoss ssim_loss;
  cv::Mat pred_img, target_img, d_ssim;
  int it = 0;
  for (it = 1; it <= iterations; ++it) {
    if (next >= order.size()) {
      std::shuffle(order.begin(), order.end(), rng);
      next = 0;
    }
    const TrainImage& im = images[order[next++]];
    const ImageKey key{im.frame, im.camera};
    Eigen::Isometry3d pose = im.pose;
    if (o.pose_refinement) pose = pose * model.camera_correction[im.camera].transform() * model.image_correction[key].transform();
    model.place(s, im.time, {}, placed, &source);
    // Coarse to fine: half resolution for the first part of training (a quarter of the pixels).
    const bool coarse = it <= coarse_iterations(iterations, o.coarse_share) && im.cam.width >= 128;
    const scene::Camera cam = coarse ? scaled_camera(im.cam, im.cam.width / 2) : im.cam;
    cv::Mat coarse_rgb;
    if (coarse) cv::resize(im.rgb, coarse_rgb, cv::Size(cam.width, cam.height), 0, 0, cv::INTER_AREA);
    const cv::Mat& target_rgb = coarse ? coarse_rgb : im.rgb;
    const GsView view = make_view(cam, pose);
    const GsImage out = raster.forward(placed, &model.sky, view);
    // L1 in sRGB through the exposure; dL/dradiance per pixel.
    const double e = im.exposure * std::exp(double(model.log_exposure[key]));
    cv::Mat d_rad(out.radiance.size(), CV_32FC3);
    const double n = double(out.radiance.total()) * 3;
    double l1 = 0, se = 0, d_log_e = 0;
    static const OetfTable oetf;
    if (o.ssim_weight > 0) pred_img.create(out.radiance.size(), CV_32FC3), target_img.create(out.radiance.size(), CV_32FC3);
    for (int y = 0; y < out.radiance.rows; ++y)
      for (int x = 0; x < out.radiance.cols; ++x) {
        const cv::Vec3f r = out.radiance.at<cv::Vec3f>(y, x);
        const cv::Vec3b t8 = target_rgb.at<cv::Vec3b>(y, x);
        cv::Vec3f& g = d_rad.at<cv::Vec3f>(y, x);
        for (int c = 0; c < 3; ++c) {
          const double lin = e * r[c];
          // The OETF continued linearly above 1, so overexposure still has a gradient.
          double pred, slope;
          oetf.eval(lin, pred, slope);
          const double target = t8[c] / 255.0;
          double diff = pred - target;
          if (t8[c] == 255 && diff > 0) diff = 0;  // saturated: anything brighter is right
          l1 += std::abs(diff);
          se += std::min(1.0, std::abs(diff)) * std::min(1.0, std::abs(diff));
          const double dpred = (diff > 0 ? 1.0 : (diff < 0 ? -1.0 : 0.0)) / n;
          if (o.ssim_weight > 0) {  // finished below, with the SSIM term
            g[c] = float(dpred);
            pred_img.at<cv::Vec3f>(y, x)[c] = float(std::min(pred, 1.0));
            target_img.at<cv::Vec3f>(y, x)[c] = float(target);
            continue;
          }
          g[c] = float(dpred * slope * e);
          d_log_e += dpred * slope * lin;
        }
      }
    if (o.ssim_weight > 0) {
      // (1 - w) L1 + w (1 - SSIM); SSIM sees the clipped image, as the metric does.
      ssim_loss.value_and_gradient(pred_img, target_img, d_ssim);
      const double w = o.ssim_weight;
      for (int y = 0; y < out.radiance.rows; ++y)
        for (int x = 0; x < out.radiance.cols; ++x) {
          const cv::Vec3f r = out.radiance.at<cv::Vec3f>(y, x);
          cv::Vec3f& g = d_rad.at<cv::Vec3f>(y, x);
          for (int c = 0; c < 3; ++c) {
            const double lin = e * r[c];
            double pred, slope;
            oetf.eval(lin, pred, slope);
            const double dpred = (1 - w) * g[c] - (pred < 1.0 ? w * d_ssim.at<cv::Vec3f>(y, x)[c] : 0.0);
            g[c] = float(dpred * slope * e);
            d_log_e += dpred * slope * lin;
          }
        }
    }
    l1 /= n;
    const double psnr = 10 * std::log10(1.0 / std::max(se / n, 1e-10));
    loss_ema = it == 1 ? l1 : 0.98 * loss_ema + 0.02 * l1;
    recent_psnr.push_back(psnr);
    if (recent_psnr.size() > 100) recent_psnr.erase(recent_psnr.begin());
    grads.reset(placed.size(), size_t(model.sky.width() * model.sky.height()));
    // LiDAR depth: expected depth (D / A) at each point's pixel against its camera depth,
    // relative L1. The point's own depth moves with the pose, too.
    cv::Mat d_depth, d_alpha;
    Eigen::Matrix<float, 6, 1> lidar_pose_grad = Eigen::Matrix<float, 6, 1>::Zero();
    if (o.depth_weight > 0 && !im.lidar.empty()) {
      d_depth = cv::Mat(out.depth.size(), CV_32F, cv::Scalar(0));
      d_alpha = cv::Mat(out.depth.size(), CV_32F, cv::Scalar(0));
      const Eigen::Matrix3f Rt = view.rotation.transpose();
      const float w = float(o.depth_weight) / float(im.lidar.size());
      for (const auto& X : im.lidar) {
        const Eigen::Vector3f p = Rt * (X - view.center);
        if (p.z() < 0.5f) continue;
        const int u = int(std::lround(view.fx * p.x() / p.z() + view.cx)), v = int(std::lround(view.fy * p.y() / p.z() + view.cy));
        if (u < 0 || v < 0 || u >= out.depth.cols || v >= out.depth.rows) continue;
        const float A = out.alpha.at<float>(v, u), D = out.depth.at<float>(v, u);
        if (A < 0.5f) continue;
        const float e = D / A - p.z();
        const float g = (e > 0 ? w : -w) / p.z();
        d_depth.at<float>(v, u) += g / A;
        d_alpha.at<float>(v, u) += -g * D / (A * A);
        // d(-z)/d twist: z' = z - (w x p).z - t.z -> dz/dw = (-p.y, p.x, 0), dz/dt = (0, 0, -1).
        lidar_pose_grad += -g * (Eigen::Matrix<float, 6, 1>() << -p.y(), p.x(), 0, 0, 0, -1).finished();
      }
    }
    // The poses learn from everything but the ground where moving objects' shadows travel:
    // on the demo scene a truck driving beside the car fills front_left, and its shadow's smear
    // turned that camera's roll the wrong way.
    std::vector<uint8_t> blind;
    if (o.pose_refinement) {
      blind = moving_shadow_band(s, moving, placed, source, model.owner, im.time, o.pose_blind_pad_m);
      raster.pose_blind = &blind;
    }
    raster.backward(placed, &model.sky, d_rad, d_depth, d_alpha, grads);
    raster.pose_blind = nullptr;
    grads.pose += lidar_pose_grad;
    // Placed gradients back to the model (objects: from the world into their frames).
    param_grads.assign(model.gaussians.p.size(), 0.0f);
    std::vector<std::optional<Eigen::Isometry3f>> opose(model.objects.size());
    for (size_t k = 0; k < s.objects.size() && k < opose.size(); ++k)
      if (const auto p = object_pose(s, s.objects[k], im.time)) opose[k] = p->cast<float>();
    for (size_t j = 0; j < placed.size(); ++j) {
      if (!grads.visible[j]) continue;
      const size_t i = size_t(source[j]);
      const float* gj = &grads.gaussians[j * kParamCount];
      float* gi = &param_grads[i * kParamCount];
      std::copy(gj, gj + kParamCount, gi);
      screen_accum[i] += grads.screen[j];
      denom[i] += 1;
      const int own = model.owner[i];
      if (own < 0 || !opose[size_t(own)]) continue;
      const Eigen::Matrix3f R = opose[size_t(own)]->linear();
      const Eigen::Vector3f dp = R.transpose() * Eigen::Vector3f(gj[kPosX], gj[kPosY], gj[kPosZ]);
      gi[kPosX] = dp.x(), gi[kPosY] = dp.y(), gi[kPosZ] = dp.z();
      const Eigen::Quaternionf q(R);
      Eigen::Matrix4f L;
      L << q.w(), -q.x(), -q.y(), -q.z(), q.x(), q.w(), -q.z(), q.y(), q.y(), q.z(), q.w(), -q.x(), q.z(), -q.y(), q.x(), q.w();
      const Eigen::Vector4f dq = L.transpose() * Eigen::Vector4f(gj[kRotW], gj[kRotX], gj[kRotY], gj[kRotZ]);
      for (int k = 0; k < 4; ++k) gi[kRotW + k] = dq[k];
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3f dk = R.transpose() * Eigen::Vector3f(gj[kColor + 4 * c + 1], gj[kColor + 4 * c + 2], gj[kColor + 4 * c + 3]);
        gi[kColor + 4 * c + 1] = dk.x(), gi[kColor + 4 * c + 2] = dk.y(), gi[kColor + 4 * c + 3] = dk.z();
      }
    }
    // Learning rates: position decays from 1.6e-4 to 1.6e-6 of the scene's extent. The others
    // are 4 times the earlier ones (for scale, rotation and opacity, 3D Gaussian splatting's,
    // meant for 30 000 iterations; the presets run 500-6000). On the demo scene at 600
    // iterations, 4x gave 25.2 dB held out against 23.9 (2x: 25.0, 8x: 24.4).
    const float progress = float(it) / float(iterations);
    float lr[kParamCount];
    const float pos_lr = float(1.6e-4 * extent * std::pow(0.01, progress));
    // Colour's rates fall tenfold over training: the captured images are noisy, and Adam at a
    // fixed rate keeps each colour wandering around the noise's mean (blotches on flat paint).
    // Demo scene, 64-sample views: 600 iterations 27.61 -> 27.89 dB, 1800 30.05 -> 30.26. Falling
    // to 0.03 or from half-way did the same; scale, rotation and opacity falling too: 26.25.
    const float colour_rate = std::pow(0.1f, progress);
    for (int k = 0; k < 3; ++k) lr[kPosX + k] = pos_lr, lr[kScaleX + k] = 2e-2f;
    for (int k = 0; k < 4; ++k) lr[kRotW + k] = 4e-3f;
    lr[kOpacity] = 0.1f;
    for (int c = 0; c < 3; ++c) {
      lr[kColor + 4 * c] = 4e-2f * colour_rate;
      for (int k = 1; k < 4; ++k) lr[kColor + 4 * c + k] = 4e-3f * colour_rate;
    }
    adam.step(model.gaussians.p.data(), param_grads.data(), param_grads.size(), lr, kParamCount, it);
    const float sky_lr = 1e-2f;
    sky_adam.step(model.sky.data().data(), grads.sky.data(), grads.sky.size(), &sky_lr, 1, it);
    if (learn_exposure && it > 50) {
      auto& st = exp_state[key];
      st[1] = 0.9f * st[1] + 0.1f * float(d_log_e);
      st[2] = 0.999f * st[2] + 0.001f * float(d_log_e * d_log_e);
      model.log_exposure[key] -= 2e-3f * st[1] / (std::sqrt(st[2]) + 1e-12f);
    }
    if (o.pose_refinement) {
      // The first camera is the rig's reference (its calibration defines the rig): only the
      // others get a per-camera correction; every image gets its own small one. The rates fall
      // tenfold over training so the poses settle; translation moves slowly since the images
      // start at their trigger time's ego pose, and calibration is mostly rotation. Measured on
      // the demo scene at 600 iterations (noise-free views, dB): 24.98 with the rates x1 from
      // 5 % of training, 25.14 decaying from 20 %, 25.27 with translation / 4, 25.41 with the
      // per-camera rotation x 4 too. Calibration starts almost at once: started with the
      // images' at 20 %, the field had learned around the side cameras' 0.3 deg error and
      // refinement left 0.17-0.21 deg of it (64-sample views: 26.88 dB); from 2 %, with moving
      // shadows left out, 0.04-0.23 deg and 27.44 dB. A camera's translation learns at 5e-5,
      // not 5e-4: Adam takes steps of its rate whatever the gradient's size, and along the
      // optical axis the gradient is weak, so at 5e-4 the side cameras wandered 7-11 mm from
      // their (exact) translation and their ground-truth views scored 0.9-1.4 dB below the same
      // views at the model's poses; at 5e-5, 1-3 mm, and the ground-truth views rose from 29.50
      // to 29.65 (benchmark) and 29.72 dB (a first run; front_left +0.6, front_right +0.4).
      const float decay = std::pow(0.1f, progress);
      if (im.camera != s.cameras.front().name && it > int(o.camera_pose_start * float(iterations)))
        cam_twist[im.camera].step(grads.pose, 8e-4f * decay, 5e-5f * decay);
      if (it > int(o.pose_start * float(iterations))) img_twist[key].step(grads.pose, 1e-4f * decay, 2.5e-4f * decay);
    }
    // Densify and prune.
    if (it >= densify_from && it <= densify_until && it % densify_every == 0) {
      Gaussians& G = model.gaussians;
      const size_t count = G.size();
      std::vector<size_t> grow;
      for (size_t i = 0; i < count; ++i)
        if (denom[i] > 0 && screen_accum[i] / denom[i] > o.densify_threshold) grow.push_back(i);
      if (debug_densify) {
        std::vector<float> avg;
        for (size_t i = 0; i < count; ++i)
          if (denom[i] > 0) avg.push_back(screen_accum[i] / denom[i]);
        std::sort(avg.begin(), avg.end());
        if (!avg.empty())
          std::fprintf(stderr, "densify it %d: %zu seen, grad p50 %.2e p90 %.2e p99 %.2e, %zu over %.1e\n", it, avg.size(),
                       avg[avg.size() / 2], avg[avg.size() * 9 / 10], avg[avg.size() * 99 / 100], grow.size(), o.densify_threshold);
      }
      const size_t room = max_gaussians > count ? max_gaussians - count : 0;
      if (grow.size() > room) {
        std::partial_sort(grow.begin(), grow.begin() + long(room), grow.end(), [&](size_t a, size_t b) {
          return screen_accum[a] / denom[a] > screen_accum[b] / denom[b];
        });
        grow.resize(room);
      }
      std::vector<uint8_t> remove(count, 0);
      std::normal_distribution<float> N(0, 1);
      for (size_t i : grow) {
        float gp[kParamCount];  // a copy: growing the array moves it
        std::copy(G.at(i), G.at(i) + kParamCount, gp);
        const Eigen::Vector3f sc(std::exp(gp[kScaleX]), std::exp(gp[kScaleY]), std::exp(gp[kScaleZ]));
        const size_t a = G.size();
        G.resize(a + 1);
        std::copy(G.at(i), G.at(i) + kParamCount, G.at(a));
        model.owner.push_back(model.owner[i]);
        if (sc.maxCoeff() > 0.01f * float(extent)) {  // large: split into two smaller ones
          const Eigen::Matrix3f R = quaternion_matrix(gp[kRotW], gp[kRotX], gp[kRotY], gp[kRotZ]) /
                                    std::max(1e-12f, Eigen::Vector4f(gp[kRotW], gp[kRotX], gp[kRotY], gp[kRotZ]).squaredNorm());
          for (size_t t : {i, a}) {
            float* q = G.at(t);
            const Eigen::Vector3f off = R * Eigen::Vector3f(N(rng) * sc.x(), N(rng) * sc.y(), N(rng) * sc.z());
            q[kPosX] += off.x(), q[kPosY] += off.y(), q[kPosZ] += off.z();
            for (int k = 0; k < 3; ++k) q[kScaleX + k] -= std::log(1.6f);
          }
        }
      }
      for (size_t i = 0; i < G.size(); ++i) {
        const float* gp = G.at(i);
        const float maxs = std::exp(std::max({gp[kScaleX], gp[kScaleY], gp[kScaleZ]}));
        if (sigmoid(gp[kOpacity]) < 0.005f || maxs > 0.5f * float(extent) || !std::isfinite(gp[kPosX])) {
          if (i >= remove.size()) remove.resize(i + 1, 0);
          remove[i] = 1;
        }
      }
      remove.resize(G.size(), 0);
      adopt_into_static_objects(G, model.owner, s, parked);
      // Compact the arrays, the optimiser's moments with them.
      std::vector<float>& m = adam.m();
      std::vector<float>& v = adam.v();
      m.resize(G.p.size(), 0.0f), v.resize(G.p.size(), 0.0f);
      size_t w = 0;
      for (size_t i = 0; i < G.size(); ++i) {
        if (remove[i]) continue;
        if (w != i) {
          std::copy(G.at(i), G.at(i) + kParamCount, G.at(w));
          std::copy(&m[i * kParamCount], &m[i * kParamCount] + kParamCount, &m[w * kParamCount]);
          std::copy(&v[i * kParamCount], &v[i * kParamCount] + kParamCount, &v[w * kParamCount]);
          model.owner[w] = model.owner[i];
        }
        ++w;
      }
      G.resize(w);
      model.owner.resize(w);
      m.resize(G.p.size()), v.resize(G.p.size());
      screen_accum.assign(w, 0.0f);
      denom.assign(w, 0.0f);
    }
    if (o.progress && (it % 10 == 0 || it == iterations)) o.progress(it, iterations, loss_ema, psnr, model.gaussians.size());
    // Stop when the loss has stopped falling after densification (over 300-iteration windows).
    if (it % 100 == 0) {
      window_losses.push_back(loss_ema);
      const size_t k = window_losses.size();
      if (it > densify_until + 300 && k >= 4 && window_losses[k - 4] - window_losses[k - 1] < 0.005 * window_losses[k - 4]) {
        report.converged = true;
        break;
      }
    }
  }
  // Exposures without a recorded value are relative: fix their mean at 1.
  if (learn_exposure) {
    bool any_unknown = false;
    for (const auto& im : images) any_unknown |= im.exposure == 1.0;
    if (any_unknown) {
      double mean = 0;
      for (const auto& [k, v] : model.log_exposure) mean += v;
      mean /= double(model.log_exposure.size());
      for (auto& [k, v] : model.log_exposure) v -= float(mean);
      for (auto& v : model.sky.data()) v += float(mean);
      for (size_t i = 0; i < model.gaussians.size(); ++i)
        for (int c = 0; c < 3; ++c) model.gaussians.at(i)[kColor + 4 * c] += float(mean);
    }
  }
  report.iterations = std::min(it, iterations);
  report.final_loss = loss_ema;
  report.train_psnr = recent_psnr.empty() ? 0 : std::accumulate(recent_psnr.begin(), recent_psnr.end(), 0.0) / double(recent_psnr.size());
  report.gaussians = model.gaussians.size();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  model.info = {{"scene", s.name},
                {"preset", o.preset},
                {"holdout", o.holdout},
                {"exposure", o.exposure},
                {"pose_refinement", o.pose_refinement},
                {"iterations", report.iterations},
                {"converged", report.converged},
                {"train_seconds", report.seconds},
                {"train_loss_l1", report.final_loss},
                {"train_psnr", report.train_psnr},
                {"gaussians", report.gaussians},
                {"resolution", {report.width, report.height}},
                {"extent_m", extent}};
  if (report_out) *report_out = report;
  return model;
}

}  // namespace chatsim::render::gs
