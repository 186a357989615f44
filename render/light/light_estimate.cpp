#include "render/light/light_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <set>

#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"
#include "common/scene/objects.hpp"
#include "render/color.hpp"
#include "render/equirect.hpp"
#include "render/image_io.hpp"
#include "render/parallel.hpp"
#include "render/light/shadow_cue.hpp"
#include "render/sampling.hpp"

namespace chatsim::render::light {
namespace {

constexpr int kClipped = 250;
constexpr unsigned kSkySampleSeed = 7;
// The shadow evidence's weight against the sky fit's error: 0.15 before the outline agreement,
// which lowers real shadows' evidence too. With it, 0.15 let the sky fit win on one of the five
// demo scenes tried (seeds 1-5: its clip estimate 101 deg off); 0.3 did as well or better than
// the estimator without agreement on all five.
constexpr double kShadowWeight = 0.3;
// How much worse (mean squared log error) the sky fit through a visible sun blob may be than the
// best direction's. A Preetham sky fits a sunset's glow loosely: on blender-data's sunset the
// best direction was 15-17 deg off the visible sun and fitted better by 0.005-0.007; the false
// blobs tried (sky between leaves or roofs) fitted worse by 0.03 or more.
constexpr double kSunBlobFitSlack = 0.01;

Eigen::Vector3f pixel_dir(const LightView& v, double x, double y) {
  const Eigen::Vector3d d((x - v.camera.cx) / v.camera.fx, (y - v.camera.cy) / v.camera.fy, 1);
  return (v.camera_to_world.linear() * d).normalized().cast<float>();
}

Rgb linear_pixel(const LightView& v, const cv::Vec3b& p) {
  const auto& t = srgb_to_linear_table();
  return Rgb(t[p[0]], t[p[1]], t[p[2]]) / float(v.exposure);
}

struct SkySample {
  Eigen::Vector3f dir;
  Rgb radiance;
  bool clipped;
};

Eigen::Vector3f from_angles(double az, double el) {
  return Eigen::Vector3f(float(std::cos(el) * std::cos(az)), float(std::cos(el) * std::sin(az)), float(std::sin(el)));
}

// Log-luminance error of a sky model against the samples, with the best scale. A clipped sample
// only says the sky is at least that bright there (censored): it costs only where the model
// falls below it. Without that, an overexposed sky keeps just its darkest pixels, those far from
// the sun, and the fit turns the sun away.
// Robust: the scale from the samples within a factor kTrimFactor of the model, and each
// sample's cost capped there, so that specks of a pale roof or facade left in the sky mask
// neither pull the scale (and with it the sun's intensity the shadows give) nor the direction.
struct Fit {
  double error = 1e30, log_scale = 0;  // without unclipped samples: worse than any fit
  bool measured = false;               // some unclipped sky sample was fitted
  std::optional<double> reported() const { return measured ? std::optional<double>(error) : std::nullopt; }
  std::optional<double> reported_rms() const { return measured ? std::optional<double>(std::sqrt(error)) : std::nullopt; }
};
constexpr double kTrimFactor = 1.5;
Fit fit_model(const std::vector<SkySample>& samples, const std::function<float(const Eigen::Vector3f&)>& model, bool robust) {
  std::vector<double> exact, at_least;
  exact.reserve(samples.size());
  for (const auto& s : samples) {
    const double r = std::log(std::max(luminance(s.radiance), 1e-9f)) - std::log(std::max(model(s.dir), 1e-9f));
    (s.clipped ? at_least : exact).push_back(r);
  }
  Fit f;
  if (exact.empty()) return f;
  f.measured = true;
  // The mean over the samples that count at scale b (the exact within `band` of it, the clipped
  // short of the model by less than `band`), iterated to its fixed point.
  const auto settle = [&](double b, double band) {
    for (int it = 0; it < 30; ++it) {
      double sum = 0;
      size_t n = 0;
      for (double r : exact)
        if (std::abs(r - b) < band) sum += r, ++n;
      for (double r : at_least)
        if (r > b && r - b < band) sum += r, ++n;
      if (n == 0) break;
      const double next = sum / double(n);
      if (std::abs(next - b) < 1e-6) break;
      b = next;
    }
    return b;
  };
  // Without a band, the scale minimising the sum of squares (exact) plus the squared shortfalls
  // (clipped): a convex 1-D problem whose minimum is that fixed point. Robust: from there, only
  // the samples within the band.
  double b = 0;
  for (double r : exact) b += r;
  b = settle(b / double(exact.size()), std::numeric_limits<double>::infinity());
  const double band = std::log(kTrimFactor);
  if (robust) b = settle(b, band);
  f.log_scale = b;
  const auto cost = [&](double d) { return robust ? std::min(d * d, band * band) : d * d; };
  double e = 0;
  for (double r : exact) e += cost(r - b);
  for (double r : at_least)
    if (r > b) e += cost(r - b);
  f.error = e / double(exact.size() + at_least.size());
  return f;
}

// The clear (Preetham) sky's fit for one sun direction and turbidity.
Fit clear_sky_fit(const std::vector<SkySample>& samples, const Eigen::Vector3f& sun, double turbidity, bool robust) {
  SkyParams p;
  p.sun_direction = sun;
  p.turbidity = float(turbidity);
  p.compute_ground = false;
  const Sky sky(p);
  return fit_model(samples, [&](const Eigen::Vector3f& d) { return luminance(sky.radiance(d)); }, robust);
}

// How many instants (frames) the views show: boxes are matched to the views of theirs.
int count_instants(const std::vector<LightView>& views) {
  std::set<int> frames;
  for (const auto& v : views) frames.insert(v.frame);
  return std::max<int>(1, int(frames.size()));
}

// Sky samples per view and kind (measured, clipped): about 1000 per instant's views.
size_t sky_samples_per_view(int instants) { return size_t(std::max(200, 1000 / instants)); }

// The coarse grid of sun directions both searches use: 72 azimuths by 17 elevations (5-85 deg),
// 5 degrees apart; direction i is azimuth i / 17, elevation i % 17.
constexpr int kGridElevations = 17, kGridDirections = 72 * kGridElevations;
double grid_azimuth(int i) { return (i / kGridElevations) * 5 * M_PI / 180; }
double grid_elevation(int i) { return (i % kGridElevations + 1) * 5 * M_PI / 180; }

// Sky samples of one view: random subsets of its measured and of its clipped sky pixels, each
// capped on its own, so an overexposed sky does not crowd out the few pixels that say how
// bright it is. Returns how many of its sky pixels are clipped.
long sample_sky(const LightView& v, const cv::Mat& mask, size_t per_view, std::mt19937& rng, std::vector<SkySample>& out) {
  std::vector<cv::Point> measured, clipped_px;
  for (int y = 0; y < mask.rows; ++y)
    for (int x = 0; x < mask.cols; ++x)
      if (mask.at<uchar>(y, x)) {
        const cv::Vec3b c = v.rgb.at<cv::Vec3b>(y, x);
        (c[0] >= kClipped || c[1] >= kClipped || c[2] >= kClipped ? clipped_px : measured).emplace_back(x, y);
      }
  const long clipped_count = long(clipped_px.size());  // before the sampling caps it
  for (auto* set : {&measured, &clipped_px}) {
    std::shuffle(set->begin(), set->end(), rng);
    if (set->size() > per_view) set->resize(per_view);
    for (const auto& p : *set) out.push_back({pixel_dir(v, p.x, p.y), linear_pixel(v, v.rgb.at<cv::Vec3b>(p)), set == &clipped_px});
  }
  return clipped_count;
}

// How much darker the ground is where boxes would cast their shadows for a sun direction.
// The sky's typical brightness in a view (luminance `g` over its sky `mask`; 0 without sky):
// a sun's aureole is far above it.
float sky_median_of(const cv::Mat& mask, const cv::Mat& g) {
  std::vector<float> sky_lum;
  for (int y = 0; y < mask.rows; y += 2)
    for (int x = 0; x < mask.cols; x += 2)
      if (mask.at<uchar>(y, x)) sky_lum.push_back(g.at<float>(y, x));
  if (sky_lum.empty()) return 0;
  std::nth_element(sky_lum.begin(), sky_lum.begin() + long(sky_lum.size() / 2), sky_lum.end());
  return sky_lum[sky_lum.size() / 2];
}

// The most sun-like blob among a view's clipped pixels (`level`): compact, surrounded by sky or
// glare (`glare`: pixels with any channel clipped), and by an aureole far brighter than the
// view's sky (`mask`, its median `sky_median`) or by glare over half its ring (a clipped glow
// hides how bright the aureole is); its score is area times the aureole's brightness, 0 without
// one.
struct SunBlob {
  double score = 0;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
};
SunBlob find_sun_blob(const LightView& v, const cv::Mat& mask, const cv::Mat& g, float sky_median, const cv::Mat& level,
                      const cv::Mat& glare) {
  SunBlob best;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(level, labels, stats, centroids);
  for (int k = 1; k < n; ++k) {
    const int area = stats.at<int>(k, cv::CC_STAT_AREA);
    if (area < 4 || size_t(area) > v.rgb.total() / 50) continue;
    // Round and compact (not a white wall's edge).
    const int bw = stats.at<int>(k, cv::CC_STAT_WIDTH), bh = stats.at<int>(k, cv::CC_STAT_HEIGHT);
    if (double(area) < 0.45 * bw * bh || std::max(bw, bh) > 3 * std::min(bw, bh)) continue;
    // Surrounded by sky or glare (a white window or car is surrounded by facade or road), and
    // that surround much brighter than the sky elsewhere (the aureole).
    const double cx = centroids.at<double>(k, 0), cy = centroids.at<double>(k, 1);
    const double r = std::sqrt(area / M_PI);
    int ring_n = 0, ring_sky = 0, ring_glare = 0;
    double ring_lum = 0;
    for (int i = 0; i < 48; ++i) {
      const double ang = 2 * M_PI * i / 48;
      for (double rr : {2.0 * r + 2, 3.0 * r + 4}) {
        const int x = int(std::lround(cx + rr * std::cos(ang))), y = int(std::lround(cy + rr * std::sin(ang)));
        if (x < 0 || y < 0 || x >= v.rgb.cols || y >= v.rgb.rows) continue;
        ++ring_n;
        // Sky, or glare too bright for the sky mask to take. The aureole is measured there
        // only: a low sun's ring reaches the dark horizon below it.
        ring_glare += glare.at<uchar>(y, x) != 0;
        if (mask.at<uchar>(y, x) || glare.at<uchar>(y, x) || g.at<float>(y, x) >= sky_median) ++ring_sky, ring_lum += g.at<float>(y, x);
      }
    }
    if (ring_n < 16 || ring_sky < 0.6 * ring_n) continue;
    const double aureole = ring_lum / std::max(1, ring_sky) / std::max(1e-9f, sky_median);
    if (sky_median > 0 && aureole < 1.5 && ring_glare < 0.5 * ring_n) continue;
    const double score = area * aureole;
    if (score <= best.score) continue;
    best.score = score;
    best.direction = pixel_dir(v, cx, cy).cast<double>();
  }
  return best;
}

}  // namespace

cv::Mat sky_mask(const LightView& v) {
  const int w = v.rgb.cols, h = v.rgb.rows;
  cv::Mat gray, grad_x, grad_y;
  cv::cvtColor(v.rgb, gray, cv::COLOR_RGB2GRAY);
  cv::GaussianBlur(gray, gray, cv::Size(3, 3), 0);
  cv::Sobel(gray, grad_x, CV_32F, 1, 0);
  cv::Sobel(gray, grad_y, CV_32F, 0, 1);
  cv::Mat grad = cv::abs(grad_x) + cv::abs(grad_y);
  std::vector<uchar> above;
  // 1: above the horizon; 2: clearly below it (where a smooth bright region is a surface); 3:
  // between (links the two).
  cv::Mat side(h, w, CV_8U, cv::Scalar(3));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float up = pixel_dir(v, x, y).z();
      if (up > 0.02f) {
        side.at<uchar>(y, x) = 1;
        above.push_back(gray.at<uchar>(y, x));
      } else if (up < -0.03f) {
        side.at<uchar>(y, x) = 2;
      }
    }
  cv::Mat cand(h, w, CV_8U, cv::Scalar(0));
  if (above.empty()) return cand;
  std::nth_element(above.begin(), above.begin() + long(above.size() * 95 / 100), above.end());
  const int bright = int(above[above.size() * 95 / 100] * 0.55);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uchar sd = side.at<uchar>(y, x);
      const cv::Vec3b p = v.rgb.at<cv::Vec3b>(y, x);
      const bool smooth = grad.at<float>(y, x) < 40;  // Sobel of a 3x3-blurred image: gentle gradients only
      // Not reddish and not greenish (the sunlit top of a tree against a white sky is bright).
      const bool skyish = p[2] >= 0.85 * p[0] && gray.at<uchar>(y, x) >= bright && p[1] <= 1.1 * p[2] + 4;
      const bool clipped = p[0] >= kClipped && p[1] >= kClipped && p[2] >= kClipped;
      // Below the horizon only smooth, unclipped candidates: a clipped white marking or wall
      // there says nothing about the region above.
      if ((smooth && skyish && !(sd == 2 && clipped)) || (sd == 1 && clipped)) cand.at<uchar>(y, x) = 255;
    }
  // Only regions reached from the top of the image, and not continuing well below the horizon:
  // the sky ends at or above it, a smooth pale wall or a truck's side (reaching the top of the
  // image too) goes on below it.
  cv::Mat labels;
  const int n = cv::connectedComponents(cand, labels, 4, CV_32S);
  std::vector<uint8_t> keep(size_t(n), 0);
  std::vector<long> n_above(size_t(n), 0), n_below(size_t(n), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int l = labels.at<int>(y, x);
      if (side.at<uchar>(y, x) == 1) n_above[size_t(l)]++;
      if (side.at<uchar>(y, x) == 2) n_below[size_t(l)]++;
    }
  for (int y = 0; y < std::max(1, h / 20); ++y)
    for (int x = 0; x < w; ++x) keep[size_t(labels.at<int>(y, x))] = 1;
  keep[0] = 0;
  for (int l = 1; l < n; ++l)
    if (n_below[size_t(l)] > n_above[size_t(l)] / 10) keep[size_t(l)] = 0;
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (keep[size_t(labels.at<int>(y, x))] && side.at<uchar>(y, x) == 1) mask.at<uchar>(y, x) = 255;
  return mask;
}

EnvMap LightEstimate::dome(int width, int height) const {
  SkyParams p = sky;
  p.compute_ground = true;
  const Sky model(p);
  EnvMap m = model.to_env_map(width, height, true);
  for (int y = 0; y < m.height(); ++y)
    for (int x = 0; x < m.width(); ++x) m.at(x, y) *= scale;
  m.update();
  return m;
}

nlohmann::json LightEstimate::to_json(const std::string& sky_exr) const {
  const Eigen::Vector3f d = sky.sun_direction.normalized();
  nlohmann::json j{{"sky_type", sunny ? "sunny" : "overcast"},
                   {"sun_direction_world", {d.x(), d.y(), d.z()}},
                   {"sun_radiance_rgb", {sun_radiance.x(), sun_radiance.y(), sun_radiance.z()}},
                   {"sun_solid_angle_sr", sun_solid_angle_sr()},
                   {"sky_exr", sky_exr},
                   {"sky_mapping", std::string(kEquirectMapping) + "; the sun disc is not in the EXR; below the horizon a diffuse ground"},
                   {"sun_cue", sun_cue},
                   {"turbidity", sky.turbidity},
                   {"fit_rms_log_error", fit_error ? nlohmann::json(std::sqrt(*fit_error)) : nlohmann::json(nullptr)},
                   {"sky_pixels", sky_pixels}};
  if (!sunny) j["sun_radiance_rgb"] = {0.0, 0.0, 0.0};
  return j;
}

LightEstimate estimate_light(const std::vector<LightView>& views, const std::vector<GroundBox>& boxes) {
  LightEstimate est;
  const int instants = count_instants(views);
  std::mt19937 rng(kSkySampleSeed);
  std::vector<SkySample> samples;
  double blue = 0;
  int blue_n = 0;
  Eigen::Vector3d sun_visible = Eigen::Vector3d::Zero();
  double sun_visible_area = 0;
  std::vector<cv::Mat> gray, below;  // linear luminance; ground directions (below the horizon)
  const size_t per_view = sky_samples_per_view(instants);
  long sky_clipped_px = 0;
  for (const auto& v : views) {
    const cv::Mat mask = sky_mask(v);
    cv::Mat g(v.rgb.rows, v.rgb.cols, CV_32F);
    // One pass: linear luminance for the shadow cue, the ground's directions (below the
    // horizon), and the clipped pixels a visible sun may be (a low sun is orange: one clipped
    // channel is enough) above it.
    cv::Mat b(v.rgb.rows, v.rgb.cols, CV_8U, cv::Scalar(0)), clipped(v.rgb.rows, v.rgb.cols, CV_8U, cv::Scalar(0));
    cv::Mat clipped_two(v.rgb.rows, v.rgb.cols, CV_8U, cv::Scalar(0));
    for (int y = 0; y < v.rgb.rows; ++y)
      for (int x = 0; x < v.rgb.cols; ++x) {
        const cv::Vec3b p = v.rgb.at<cv::Vec3b>(y, x);
        g.at<float>(y, x) = luminance(linear_pixel(v, p));
        const float up = pixel_dir(v, x, y).z();
        if (up < -0.01f) b.at<uchar>(y, x) = 255;
        if (up <= -0.02f) continue;
        const int n_clipped = (p[0] >= kClipped) + (p[1] >= kClipped) + (p[2] >= kClipped);
        if (n_clipped >= 1) clipped.at<uchar>(y, x) = 255;
        if (n_clipped >= 2) clipped_two.at<uchar>(y, x) = 255;
      }
    gray.push_back(g);
    below.push_back(b);
    // A sun low in a glowing sky clips one channel over a wide patch around it: its disc is
    // the smaller patch where two channels clip.
    const float sky_median = sky_median_of(mask, g);
    for (const cv::Mat& level : {clipped, clipped_two}) {
      const SunBlob blob = find_sun_blob(v, mask, g, sky_median, level, clipped);
      if (blob.score > sun_visible_area) sun_visible_area = blob.score, sun_visible = blob.direction;
    }
    const size_t first = samples.size();
    sky_clipped_px += sample_sky(v, mask, per_view, rng, samples);
    for (size_t k = first; k < samples.size(); ++k)
      if (!samples[k].clipped && samples[k].radiance.x() > 0) blue += samples[k].radiance.z() / samples[k].radiance.x(), ++blue_n;
    est.sky_pixels += cv::countNonZero(mask);
  }
  const double blue_ratio = blue_n > 0 ? blue / blue_n : 1.0;
  // Overcast: CIE, one parameter.
  // Robust fits where vehicles are measured: on the demo street the sky mask keeps specks of
  // truck roofs and facades. Without vehicles (blender-data's panoramas) the robust fit was
  // worse: the blob slack and the sunny thresholds below were set on squared errors.
  const bool robust = !boxes.empty();
  const Fit overcast = fit_model(samples, [](const Eigen::Vector3f& d) { return (1 + 2 * std::max(d.z(), 0.0f)) / 3; }, robust);
  // Clear: Preetham over sun directions and turbidities, with the shadow cue where boxes are.
  struct Candidate {
    double az = 0, el = 0, turbidity = 3, cost = 1e30;
    Fit fit;
    ShadowCue cue;
  };
  // The best turbidity for one sun direction; the shadow cue does not depend on turbidity, so
  // it is measured once per direction.
  auto evaluate = [&](double az, double el, const std::vector<double>& turbidities) {
    Candidate best_t{az, el, 3, 1e30, {}, {}};
    ShadowCue cue;
    if (!boxes.empty()) cue = shadow_cue(views, gray, below, boxes, from_angles(az, el).cast<double>(), instants);
    for (double T : turbidities) {
      if (T < 1.8) continue;
      Candidate c{az, el, T, 0, clear_sky_fit(samples, from_angles(az, el), T, robust), cue};
      c.cost = (samples.empty() ? 0.0 : c.fit.error) - kShadowWeight * cue.evidence;
      if (c.cost < best_t.cost) best_t = c;
    }
    return best_t;
  };
  // The sky fit over all directions, refined around its best.
  // Directions are independent: evaluated in parallel, the best taken in grid order.
  std::vector<Candidate> grid(kGridDirections);
  parallel_for(kGridDirections, [&](int i) { grid[size_t(i)] = evaluate(grid_azimuth(i), grid_elevation(i), {2.5, 4.0, 6.0}); });
  Candidate best{0, 0, 3, 1e30, {}, {}};
  for (const auto& c : grid)
    if (c.cost < best.cost) best = c;
  const Candidate coarse = best;
  std::vector<Candidate> fine(81);
  parallel_for(int(fine.size()), [&](int i) {
    const double el = coarse.el + (i % 9 - 4) * M_PI / 180;
    if (el < 2 * M_PI / 180 || el > 89 * M_PI / 180) return;
    fine[size_t(i)] = evaluate(coarse.az + (i / 9 - 4) * M_PI / 180, el, {coarse.turbidity - 0.5, coarse.turbidity, coarse.turbidity + 1.0});
  });
  for (const auto& c : fine)
    if (c.cost < best.cost) best = c;
  est.sun_cue = best.cue.boxes > 0 && best.cue.score > 0.15 ? "shadows" : "sky_gradient";
  // A sun-like blob is the sun only where the sky agrees: it fits about as well as the best
  // direction (within kSunBlobFitSlack), or lies near it (then the blob is the more precise).
  // An overexposed patch of sky between roofs or a white window looks like a blob too, and the
  // sky around it says otherwise.
  bool visible = false;
  if (sun_visible_area > 0 && sun_visible.z() > 0.02) {
    const double az = std::atan2(sun_visible.y(), sun_visible.x()), el = std::asin(std::clamp(sun_visible.z(), -1.0, 1.0));
    const Candidate seen = evaluate(az, el, {2.0, 2.5, 3.0, 4.0, 5.0, 7.0});
    const double apart = std::acos(std::clamp(double(from_angles(best.az, best.el).dot(from_angles(az, el))), -1.0, 1.0));
    if (seen.cost <= best.cost + kSunBlobFitSlack || apart < 10 * M_PI / 180) {
      best = seen;
      visible = true;
      est.sun_cue = "visible";
    }
  }
  // Sunny or overcast: a blue sky, a visible sun or real shadows say sunny.
  // A clear sky model that explains the sky clearly better than an overcast one says sunny too
  // (tinted or hazy skies are not blue, but keep the gradient around the sun).
  // A sky mostly clipped (a channel at the top of its range; white in practice) says little: its
  // few measured pixels are its edges against roofs, which a Preetham sky (more free
  // parameters) fits better than an overcast one. With vehicles measured whose shadows are
  // missing, that sky's word is not taken. On the demo
  // street (seeds 1-5 sunny, 1 and 5 overcast) the clipped share of the sky was 0.10-0.49 on
  // sunny frames and 0.55-0.91 on overcast ones; the margin is narrow, so boxes decide with it.
  const double clipped_share = double(sky_clipped_px) / std::max(1, est.sky_pixels);
  const bool sky_counts = best.cue.boxes < 3 || clipped_share < 0.6;
  est.sunny = visible || best.cue.score > 0.25 ||
              (sky_counts && ((blue_ratio > 1.2 && best.fit.error < overcast.error * 1.5) || best.fit.error < overcast.error * 0.7));
  if (samples.empty() && best.cue.boxes == 0) est.sunny = false;
  est.sky.sun_direction = from_angles(best.az, best.el);
  est.sky.turbidity = float(best.turbidity);
  if (!est.sunny) {
    est.sky.overcast = true;
    est.scale = float(std::exp(overcast.log_scale) / (est.sky.overcast_zenith_kcd * kUnitsPerKcd));
    est.fit_error = overcast.reported();
    est.sun_cue = "none";
    return est;
  }
  est.scale = float(std::exp(best.fit.log_scale));
  est.fit_error = best.fit.reported();
  SkyParams p = est.sky;
  const Sky model(p);
  const Rgb model_sun = model.sun_radiance() * est.scale;
  // Lit / shadow = (E_sun + E_sky) / (v E_sky): the sun's irradiance from the sky's, where v is
  // the share of the sky a car's shadow still sees (about 0.8). A contrast under about 1 / v
  // measures no sun: the fitted sky's sun is kept rather than a black one.
  const double sun_over_sky = best.cue.ratio * 0.8 - 1;
  if (best.cue.boxes > 0 && sun_over_sky > 0.05) {
    const EnvMap dome = est.dome(128, 64);
    const double e_sky = luminance(dome.irradiance(Eigen::Vector3f::UnitZ()));
    const double e_sun = sun_over_sky * e_sky;
    const double lum = e_sun / (sun_solid_angle_sr() * std::max(0.05f, est.sky.sun_direction.z()));
    est.sun_radiance = model_sun / std::max(luminance(model_sun), 1e-9f) * float(lum);
  } else {
    est.sun_radiance = model_sun;
  }
  return est;
}

SkyFitProbe probe_clear_sky(const std::vector<LightView>& views, const Eigen::Vector3f& sun) {
  std::mt19937 rng(kSkySampleSeed);
  const size_t per_view = sky_samples_per_view(count_instants(views));
  std::vector<SkySample> samples;
  for (const auto& v : views) sample_sky(v, sky_mask(v), per_view, rng, samples);
  const std::vector<double> turbidities{2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0};
  auto best_over_turbidity = [&](const Eigen::Vector3f& d) {
    Fit best;
    for (double T : turbidities)
      if (const Fit f = clear_sky_fit(samples, d, T, false); f.error < best.error) best = f;
    return best;
  };
  // A sun on or under the horizon is fitted just above it, as the estimator's grid starts at 2 deg.
  const double el = std::max(std::asin(std::clamp(double(sun.normalized().z()), -1.0, 1.0)), 2 * M_PI / 180);
  const Fit at = best_over_turbidity(from_angles(std::atan2(sun.y(), sun.x()), el));
  std::vector<Fit> grid(kGridDirections);
  parallel_for(kGridDirections, [&](int i) { grid[size_t(i)] = best_over_turbidity(from_angles(grid_azimuth(i), grid_elevation(i))); });
  int best = 0;
  for (int i = 1; i < kGridDirections; ++i)
    if (grid[size_t(i)].error < grid[size_t(best)].error) best = i;
  SkyFitProbe out;
  out.rms_at = at.reported_rms();
  out.rms_best = grid[size_t(best)].reported_rms();
  out.best_direction = from_angles(grid_azimuth(best), grid_elevation(best));
  return out;
}

}  // namespace chatsim::render::light
