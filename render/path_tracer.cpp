#include "render/path_tracer.hpp"

#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>

#include "render/denoise.hpp"
#include "render/parallel.hpp"
#include "render/sampling.hpp"

namespace chatsim::render {

Lighting Lighting::from_sky(const Sky& sky, const EnvMap& map) {
  Lighting l;
  l.sky = &map;
  if (sky.has_sun()) {
    l.sun_direction = sky.sun_direction();
    l.sun_radiance = sky.sun_radiance();
    l.sun_cos_max = sun_cos_half_angle();
  }
  return l;
}

Ray camera_ray(const scene::Camera& cam, const Eigen::Isometry3d& c2w, float u, float v) {
  const Eigen::Vector3d d_cam((u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, 1.0);
  Ray r;
  r.origin = c2w.translation().cast<float>();
  r.direction = (c2w.linear() * d_cam).normalized().cast<float>();
  r.t_min = 1e-3f;
  return r;
}

namespace {

struct SampleResult {
  Rgb radiance = Rgb::Zero();  // light not to be smoothed (sun, reflections, sky seen directly)
  Rgb diffuse = Rgb::Zero();   // diffuse sky and bounce light at the first hit (to be smoothed)
  Rgb albedo = Rgb::Zero();    // that hit's albedo, when its light was split
  bool covered = false;       // met geometry other than the catcher
  bool on_catcher = false;
  float catcher_lit = 0, catcher_unoccluded = 0;
};

// The i-th of n x n strata in an order that spreads consecutive samples over the pixel (a
// stride near n^2 / golden ratio, coprime with n^2), instead of filling it row by row.
int stratum(int i, int n) {
  const int cells = n * n;
  int stride = std::max(1, int(std::lround(cells * 0.618)));
  while (std::gcd(stride, cells) != 1) ++stride;
  return int((long(i) * stride) % cells);
}

// Moves a ray's origin off the surface along the side it leaves from.
Eigen::Vector3f offset(const Eigen::Vector3f& p, const Eigen::Vector3f& n_facing) {
  return p + n_facing * (1e-4f * std::max(1.0f, p.cwiseAbs().maxCoeff()));
}

class Tracer {
 public:
  Tracer(const RayScene& scene, const Lighting& lighting, const RenderSettings& s)
      : scene_(scene), light_(lighting), s_(s) {}

  SampleResult trace(Ray ray, Rng& rng) const {
    SampleResult out;
    Rgb beta = Rgb::Ones();
    float prev_pdf = 0;
    bool prev_specular = true;  // the camera ray counts as "seen directly"
    bool diffuse_path = false;  // continues the first hit's diffuse lobe: light goes to `diffuse`
    for (int depth = 0;; ++depth) {
      const auto hit = scene_.intersect(ray);
      if (!hit) {
        if (depth == 0 && !s_.include_sky) break;
        if (light_.sky != nullptr) {
          const float w = prev_specular ? 1.0f : mis_weight(prev_pdf, light_.sky->pdf(ray.direction));
          add(out, beta.cwiseProduct(light_.sky->radiance(ray.direction)) * w, depth, diffuse_path);
        }
        if (light_.has_sun() && ray.direction.dot(light_.sun_direction) >= light_.sun_cos_max) {
          const float w = prev_specular ? 1.0f : mis_weight(prev_pdf, light_.sun_pdf());
          add(out, beta.cwiseProduct(light_.sun_radiance) * w, depth, diffuse_path);
        }
        break;
      }
      const Material& mat = scene_.material(hit->material);
      if (depth == 0) {
        if (mat.kind == MaterialKind::ShadowCatcher) {
          out.on_catcher = true;
          shade_catcher(*hit, ray, rng, out);
          break;
        }
        out.covered = true;
      }
      if (mat.kind == MaterialKind::Emissive) {
        add(out, beta.cwiseProduct(mat.emission), depth, diffuse_path);
        break;
      }
      // Two-sided surfaces: both normals face the side the ray came from.
      Eigen::Vector3f ng = hit->geometric_normal;
      if (ng.dot(ray.direction) > 0) ng = -ng;
      Eigen::Vector3f ns = hit->shading_normal;
      if (ns.dot(ng) < 0) ns = -ns;
      const Frame frame(ns);
      const Eigen::Vector3f wo = frame.to_local(-ray.direction);
      if (wo.z() <= 0) break;
      SurfacePoint sp{mat.albedo, mat.roughness, mat.specular};
      if (mat.texture) sp = mat.texture->shade(sp, hit->position, hit->uv, ns);
      const Bsdf bsdf(mat, sp);
      const Eigen::Vector3f origin = offset(hit->position, ng);
      // The first hit's diffuse light is kept apart for smoothing (divided by albedo later).
      const bool split = depth == 0 && s_.denoise && mat.kind == MaterialKind::Coated && sp.albedo.minCoeff() > 1e-3f;
      if (split) out.albedo = sp.albedo;
      // The sun.
      if (light_.has_sun()) {
        const Frame sun_frame(light_.sun_direction);
        const Eigen::Vector3f wi_w = sun_frame.to_world(sample_cone(rng.uniform(), rng.uniform(), light_.sun_cos_max));
        if (wi_w.dot(ng) > 0) {
          const Eigen::Vector3f wi = frame.to_local(wi_w);
          const Rgb f = bsdf.eval(wo, wi);
          if (f.maxCoeff() > 0 && !blocked(origin, wi_w, ray.time)) {
            const float pdf = light_.sun_pdf();
            add(out, beta.cwiseProduct(f).cwiseProduct(light_.sun_radiance) * (mis_weight(pdf, bsdf.pdf(wo, wi)) / pdf), depth,
                diffuse_path);
          }
        }
      }
      // The sky.
      if (light_.sky != nullptr) {
        float pdf = 0;
        const Eigen::Vector3f wi_w = light_.sky->sample(rng.uniform(), rng.uniform(), &pdf);
        if (pdf > 0 && wi_w.dot(ng) > 0) {
          const Eigen::Vector3f wi = frame.to_local(wi_w);
          Rgb fd, fs;
          bsdf.eval_lobes(wo, wi, fd, fs);
          if ((fd + fs).maxCoeff() > 0 && !blocked(origin, wi_w, ray.time)) {
            const Rgb light = beta.cwiseProduct(light_.sky->radiance(wi_w)) * (mis_weight(pdf, bsdf.pdf(wo, wi)) / pdf);
            if (split) {
              add(out, light.cwiseProduct(fd), depth, true);
              add(out, light.cwiseProduct(fs), depth, false);
            } else {
              add(out, light.cwiseProduct(fd + fs), depth, diffuse_path);
            }
          }
        }
      }
      if (depth + 1 > s_.max_depth) break;
      Bsdf::Sample bs;
      if (!bsdf.sample(wo, rng.uniform(), rng.uniform(), rng.uniform(), bs)) break;
      const Eigen::Vector3f wi_w = frame.to_world(bs.wi);
      if (wi_w.dot(ng) <= 0) break;
      beta = beta.cwiseProduct(bs.weight);
      if (split && !bs.specular) diffuse_path = true;
      prev_pdf = bs.pdf;
      prev_specular = false;
      if (depth >= 2) {  // Russian roulette
        const float q = std::max(0.05f, 1 - beta.maxCoeff());
        if (rng.uniform() < q) break;
        beta /= (1 - q);
      }
      ray.origin = origin;
      ray.direction = wi_w;
      ray.t_min = 0;
      ray.t_max = 1e30f;
      ray.mask = mask::kAll;
    }
    return out;
  }

 private:
  void add(SampleResult& out, Rgb c, int depth, bool diffuse) const {
    if (!c.allFinite()) return;
    if (depth > 0 && s_.clamp_indirect > 0 && c.maxCoeff() > s_.clamp_indirect) c *= s_.clamp_indirect / c.maxCoeff();
    (diffuse ? out.diffuse : out.radiance) += c;
  }

  bool blocked(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir, float time, uint32_t mask = mask::kAll) const {
    Ray r;
    r.origin = origin;
    r.direction = dir;
    r.t_min = 0;
    r.time = time;
    r.mask = mask & ~mask::kCatcher;  // the catcher is a receiver, never a blocker
    return scene_.occluded(r);
  }

  // The ratio of light reaching the catcher with and without the objects above it, from the
  // same light samples (a diffuse ground: irradiance ratio).
  void shade_catcher(const Hit& hit, const Ray& ray, Rng& rng, SampleResult& out) const {
    Eigen::Vector3f n = hit.geometric_normal;
    if (n.dot(ray.direction) > 0) n = -n;
    const Eigen::Vector3f origin = offset(hit.position, n);
    for (int k = 0; k < std::max(1, s_.catcher_light_samples); ++k) {
      if (light_.has_sun()) {
        const Frame sf(light_.sun_direction);
        const Eigen::Vector3f wi = sf.to_world(sample_cone(rng.uniform(), rng.uniform(), light_.sun_cos_max));
        const float c = wi.dot(n);
        if (c > 0) {
          const float e = luminance(light_.sun_radiance) * c / light_.sun_pdf();
          out.catcher_unoccluded += e;
          if (!blocked(origin, wi, ray.time)) out.catcher_lit += e;
        }
      }
      if (light_.sky != nullptr) {
        float pdf = 0;
        const Eigen::Vector3f wi = light_.sky->sample(rng.uniform(), rng.uniform(), &pdf);
        const float c = wi.dot(n);
        if (pdf > 0 && c > 0) {
          const float e = luminance(light_.sky->radiance(wi)) * c / pdf;
          out.catcher_unoccluded += e;
          if (!blocked(origin, wi, ray.time)) out.catcher_lit += e;
        }
      }
    }
  }

  const RayScene& scene_;
  const Lighting& light_;
  const RenderSettings& s_;
};

}  // namespace

RenderedView render_view(const RayScene& scene, const Lighting& lighting, const scene::Camera& camera,
                         const Eigen::Isometry3d& c2w, const RenderSettings& s, cv::Rect region) {
  const cv::Rect full(0, 0, camera.width, camera.height);
  region = region.area() > 0 ? (region & full) : full;
  RenderedView out;
  out.region = region;
  out.radiance = cv::Mat(region.height, region.width, CV_32FC3, cv::Scalar::all(0));
  out.alpha = cv::Mat(region.height, region.width, CV_32FC1, cv::Scalar::all(0));
  out.depth = cv::Mat(region.height, region.width, CV_32FC1, cv::Scalar::all(std::numeric_limits<float>::infinity()));
  out.shadow = cv::Mat(region.height, region.width, CV_32FC1, cv::Scalar::all(1));
  if (region.area() == 0) return out;
  // For smoothing: the diffuse light over albedo, the albedo, and the centre ray's normal.
  cv::Mat diffuse_sum, albedo_sum, normals;
  if (s.denoise) {
    diffuse_sum = cv::Mat(region.height, region.width, CV_32FC3, cv::Scalar::all(0));
    albedo_sum = cv::Mat(region.height, region.width, CV_32FC3, cv::Scalar::all(0));
    normals = cv::Mat(region.height, region.width, CV_32FC3, cv::Scalar::all(0));
  }
  const Eigen::Matrix3f world_to_cam = c2w.linear().transpose().cast<float>();
  const Tracer tracer(scene, lighting, s);
  const int spp = std::max(1, s.spp);
  const int strata = std::max(1, int(std::floor(std::sqrt(float(spp)))));
  auto corners_clear = [&](int x, int y) {  // at the shutter's opening and closing (motion blur)
    for (const float t : {s.shutter_open, s.shutter_close})
      for (const float dx : {-0.5f, 0.5f})
        for (const float dy : {-0.5f, 0.5f}) {
          Ray r = camera_ray(camera, c2w, float(x) + dx, float(y) + dy);
          r.mask = mask::kAll & ~mask::kCatcher;
          r.time = t;
          if (scene.occluded(r)) return false;
        }
    return true;
  };
  std::atomic<int> rows_done{0};
  std::mutex progress_mu;
  parallel_for(region.height, [&](int ry) {
    const int y = region.y + ry;
    auto* rad = out.radiance.ptr<cv::Vec3f>(ry);
    auto* alpha = out.alpha.ptr<float>(ry);
    auto* depth = out.depth.ptr<float>(ry);
    auto* shadow = out.shadow.ptr<float>(ry);
    for (int rx = 0; rx < region.width; ++rx) {
      const int x = region.x + rx;
      Rng rng(hash_seed(s.seed, uint64_t(x), uint64_t(y), uint64_t(camera.width)));
      // Depth at the pixel centre, deterministic.
      {
        const Ray r = camera_ray(camera, c2w, float(x), float(y));
        Ray probe = r;
        probe.mask = mask::kAll & ~mask::kCatcher;
        if (const auto h = scene.intersect(probe)) {
          const Eigen::Vector3f axis = (c2w.linear().col(2)).cast<float>();
          depth[rx] = h->t * r.direction.dot(axis);
          if (s.denoise) {
            Eigen::Vector3f n = h->shading_normal;
            if (n.dot(r.direction) > 0) n = -n;
            const Eigen::Vector3f nc = world_to_cam * n;
            normals.at<cv::Vec3f>(ry, rx) = {nc.x(), nc.y(), nc.z()};
          }
        }
      }
      Rgb sum = Rgb::Zero(), diffuse = Rgb::Zero(), albedo = Rgb::Zero();
      int covered = 0, n = 0;
      float lit = 0, unoccluded = 0;
      // Early stop only where no object reaches into the pixel (its corners see none either)
      // and every sample so far met the catcher with no shadow ray blocked.
      bool open_ground = s.catcher_early_stop > 0 && !std::isfinite(depth[rx]) && corners_clear(x, y);
      for (int i = 0; i < spp; ++i) {
        if (open_ground && i >= s.catcher_early_stop) break;
        // Stratified over a grid for the first strata^2 samples, then random.
        float jx, jy;
        if (i < strata * strata) {
          const int cell = stratum(i, strata);  // the first few samples already cover the pixel
          jx = (float(cell % strata) + rng.uniform()) / float(strata);
          jy = (float(cell / strata) + rng.uniform()) / float(strata);
        } else {
          jx = rng.uniform();
          jy = rng.uniform();
        }
        Ray ray = camera_ray(camera, c2w, float(x) - 0.5f + jx, float(y) - 0.5f + jy);
        ray.time = s.shutter_open + (s.shutter_close - s.shutter_open) * rng.uniform();
        const SampleResult r = tracer.trace(ray, rng);
        ++n;
        open_ground = open_ground && r.on_catcher && r.catcher_lit == r.catcher_unoccluded;
        sum += r.radiance;
        diffuse += r.diffuse;
        albedo += r.albedo;
        covered += r.covered ? 1 : 0;
        lit += r.catcher_lit;
        unoccluded += r.catcher_unoccluded;
      }
      if (s.denoise) {
        diffuse_sum.at<cv::Vec3f>(ry, rx) = {diffuse.x(), diffuse.y(), diffuse.z()};
        albedo_sum.at<cv::Vec3f>(ry, rx) = {albedo.x(), albedo.y(), albedo.z()};
      } else {
        sum += diffuse;
      }
      // Averages over the n samples taken (fewer than spp after an early stop). The denoised
      // sums above are divided by spp later; an early-stopped pixel adds nothing to them (the
      // catcher has no diffuse or albedo), so that stays right.
      sum /= float(n);
      rad[rx] = {sum.x(), sum.y(), sum.z()};
      alpha[rx] = float(covered) / float(n);
      shadow[rx] = unoccluded > 0 ? std::clamp(lit / unoccluded, 0.0f, 1.0f) : 1.0f;
    }
    const int done = ++rows_done;
    if (s.progress && (done % 8 == 0 || done == region.height)) {
      std::lock_guard lock(progress_mu);
      s.progress(float(done) / float(region.height));
    }
  }, s.threads);
  if (s.denoise) {
    // Light over albedo (per pixel, albedo-weighted over its samples), smoothed, times albedo.
    cv::Mat illum(region.height, region.width, CV_32FC3, cv::Scalar::all(0));
    cv::Mat valid(region.height, region.width, CV_8UC1, cv::Scalar::all(0));
    for (int y = 0; y < region.height; ++y)
      for (int x = 0; x < region.width; ++x) {
        const cv::Vec3f a = albedo_sum.at<cv::Vec3f>(y, x), d = diffuse_sum.at<cv::Vec3f>(y, x);
        if (std::min({a[0], a[1], a[2]}) <= 1e-6f || !std::isfinite(out.depth.at<float>(y, x))) {
          out.radiance.at<cv::Vec3f>(y, x) += d / float(spp);  // nothing to smooth: keep as is
          continue;
        }
        illum.at<cv::Vec3f>(y, x) = {d[0] / a[0], d[1] / a[1], d[2] / a[2]};
        valid.at<uchar>(y, x) = 1;
      }
    const cv::Mat smooth = smooth_illumination(illum, normals, out.depth, valid, camera, region.tl());
    for (int y = 0; y < region.height; ++y)
      for (int x = 0; x < region.width; ++x)
        if (valid.at<uchar>(y, x)) {
          const cv::Vec3f a = albedo_sum.at<cv::Vec3f>(y, x) / float(spp), l = smooth.at<cv::Vec3f>(y, x);
          out.radiance.at<cv::Vec3f>(y, x) += cv::Vec3f(a[0] * l[0], a[1] * l[1], a[2] * l[2]);
        }
  }
  return out;
}

}  // namespace chatsim::render
