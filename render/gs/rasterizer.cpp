#include "render/gs/rasterizer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "render/parallel.hpp"

namespace chatsim::render::gs {
namespace {

constexpr float kMaxAlpha = 0.99f;
constexpr float kMinTransmittance = 1e-4f;
constexpr float kDilation = 0.3f;   // pixels^2 added to every 2D covariance (anti-aliasing)
constexpr float kMaxLogRadiance = 20.0f;

// The 2D footprint of one Gaussian in one view, and what backward needs to get back to it.
struct Footprint {
  Eigen::Vector3f p;        // camera-frame position
  Eigen::Matrix3f rot;      // world rotation of the Gaussian
  Eigen::Vector3f scale;    // standard deviations
  Eigen::Matrix3f cov_cam;  // camera-frame 3D covariance
  Eigen::Matrix<float, 2, 3> jac;
  float tx, ty;             // x/z and y/z after clamping to the field of view
  bool clamped_x, clamped_y;
  float A, B, C;            // 2D covariance (with dilation)
  float qn[4];              // normalised quaternion
  float qnorm;
  Eigen::Vector3f dir;      // world view direction (camera to Gaussian)
};

bool footprint(const float* g, const GsView& v, float near_m, Footprint& f) {
  const Eigen::Vector3f mu(g[kPosX], g[kPosY], g[kPosZ]);
  f.p = v.rotation.transpose() * (mu - v.center);
  if (f.p.z() < near_m) return false;
  f.qnorm = std::sqrt(g[kRotW] * g[kRotW] + g[kRotX] * g[kRotX] + g[kRotY] * g[kRotY] + g[kRotZ] * g[kRotZ]);
  if (!(f.qnorm > 1e-12f)) return false;
  for (int k = 0; k < 4; ++k) f.qn[k] = g[kRotW + k] / f.qnorm;
  f.rot = quaternion_matrix(f.qn[0], f.qn[1], f.qn[2], f.qn[3]);
  f.scale = Eigen::Vector3f(std::exp(g[kScaleX]), std::exp(g[kScaleY]), std::exp(g[kScaleZ]));
  const Eigen::Matrix3f M = f.rot * f.scale.asDiagonal();
  const Eigen::Matrix3f W = v.rotation.transpose();
  f.cov_cam = W * (M * M.transpose()) * W.transpose();
  const float lim_x = 1.3f * std::max(v.cx, float(v.width) - v.cx) / v.fx;
  const float lim_y = 1.3f * std::max(v.cy, float(v.height) - v.cy) / v.fy;
  const float z = f.p.z();
  f.tx = f.p.x() / z, f.ty = f.p.y() / z;
  f.clamped_x = std::abs(f.tx) > lim_x;
  f.clamped_y = std::abs(f.ty) > lim_y;
  f.tx = std::clamp(f.tx, -lim_x, lim_x);
  f.ty = std::clamp(f.ty, -lim_y, lim_y);
  f.jac << v.fx / z, 0, -v.fx * f.tx / z, 0, v.fy / z, -v.fy * f.ty / z;
  const Eigen::Matrix2f cov2 = f.jac * f.cov_cam * f.jac.transpose();
  f.A = cov2(0, 0) + kDilation;
  f.B = cov2(0, 1);
  f.C = cov2(1, 1) + kDilation;
  f.dir = (mu - v.center).normalized();
  return f.A * f.C - f.B * f.B > 1e-12f;
}

float clamp_log(float l) { return std::min(l, kMaxLogRadiance); }

// exp(x) for x <= 0 by 2^x = 2^floor * polynomial: branch-free, so the pixel loops below
// vectorise (relative error about 2e-7).
inline float fast_exp(float x) {
  const float t = std::max(x, -87.0f) * 1.44269504f;
  const float fi = std::floor(t);
  const float f = t - fi;
  float p = 1.8775767e-3f;
  p = p * f + 8.9893397e-3f;
  p = p * f + 5.5826318e-2f;
  p = p * f + 2.4015361e-1f;
  p = p * f + 6.9315308e-1f;
  p = p * f + 9.9999994e-1f;
  const int32_t bits = (int32_t(fi) + 127) << 23;
  return p * std::bit_cast<float>(bits);
}

constexpr int kT = 16;          // tile side (Rasterizer::kTile)
constexpr int kPix = kT * kT;

struct TileState {               // per pixel of one tile, rows of 16
  alignas(64) float T[kPix], C0[kPix], C1[kPix], C2[kPix], D[kPix], last[kPix], done[kPix], inside[kPix];
};

struct ProjView {                // the per-Gaussian values the pixel loops read
  float u, v, z, a, b, c, opacity, log_cut, r0, r1, r2;
};

// The tile-local columns [lo, hi] of tile row ly (of a tile at x0, y0) that the Gaussian's cut
// ellipse (a dx^2 + 2 b dx dy + c dy^2 <= -2 log_cut) can reach, clipped to [px0, px1]; false
// when it misses the row. Elongated footprints (the ground seen at a grazing angle) fill little
// of their bounding box: on six demo views of a trained model these spans hold 27-35 % fewer
// 8-pixel vectors than the box. Conservative by a pixel: the loops test each pixel.
inline bool row_span(const ProjView& p, int x0, int y0, int ly, int px0, int px1, int& lo, int& hi) {
  const float dy = p.v - float(y0 + ly);
  const float disc = p.b * p.b * dy * dy - p.a * (p.c * dy * dy + 2 * p.log_cut);
  if (disc < 0) return false;
  const float s = std::sqrt(disc);
  // With dx = u - x: dx in [(-b dy - s) / a, (-b dy + s) / a].
  lo = std::max(px0, int(std::floor(p.u + (p.b * dy - s) / p.a)) - 1 - x0);
  hi = std::min(px1, int(std::ceil(p.u + (p.b * dy + s) / p.a)) + 1 - x0);
  return lo <= hi;
}

// Blends one Gaussian into the rows [py0, py1] of a tile (x0, y0 its origin); j1 = its index + 1.
__attribute__((target_clones("avx2", "default")))
void blend_rows(TileState& s, const ProjView& p, int x0, int y0, int px0, int px1, int py0, int py1, float j1, float min_alpha) {
  for (int ly = py0; ly <= py1; ++ly) {
    int lo, hi;
    if (!row_span(p, x0, y0, ly, px0, px1, lo, hi)) continue;
    // Whole 8-pixel halves of the row: one vector each.
    const int c0 = lo & ~7, c1 = (hi | 7) + 1;
    const float dy = p.v - float(y0 + ly);
    const int row = ly * kT;
    for (int lx = c0; lx < c1; ++lx) {
      const int k = row + lx;
      const float dx = p.u - float(x0 + lx);
      const float power = -0.5f * (p.a * dx * dx + p.c * dy * dy) - p.b * dx * dy;
      const float alpha = std::min(kMaxAlpha, p.opacity * fast_exp(power));
      // Bitwise & (no short circuit) keeps the loop free of branches.
      const bool valid = (power <= 0) & (power >= p.log_cut) & (alpha >= min_alpha) & (s.done[k] == 0) & (s.inside[k] != 0);
      const float test_t = s.T[k] * (1 - alpha);
      const bool stop = valid & (test_t < kMinTransmittance);
      const bool add = valid & !stop;
      const float w = add ? alpha * s.T[k] : 0.0f;
      s.C0[k] += w * p.r0;
      s.C1[k] += w * p.r1;
      s.C2[k] += w * p.r2;
      s.D[k] += w * p.z;
      s.T[k] = add ? test_t : s.T[k];
      s.last[k] = add ? j1 : s.last[k];
      s.done[k] = stop ? 1.0f : s.done[k];
    }
  }
}

struct BackState {               // per pixel of one tile, walking back from the last contributor
  alignas(64) float G0[kPix], G1[kPix], G2[kPix], GD[kPix], GA[kPix], T[kPix];
  alignas(64) float A0[kPix], A1[kPix], A2[kPix], AD[kPix], AA[kPix], last[kPix];
};

// The gradient of one Gaussian (index j) over rows [py0, py1]; out: d rgb[3], opacity, u, v,
// conic a, b, c, z. Returns false when it touched no pixel.
__attribute__((target_clones("avx2", "default")))
bool unblend_rows(BackState& s, const ProjView& p, int x0, int y0, int px0, int px1, int py0, int py1, float j, float min_alpha,
                  float* out) {
  float d0 = 0, d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0, d6 = 0, d7 = 0, d8 = 0, d9 = 0, n = 0;
  for (int ly = py0; ly <= py1; ++ly) {
    int lo, hi;
    if (!row_span(p, x0, y0, ly, px0, px1, lo, hi)) continue;
    const int c0 = lo & ~7, c1 = (hi | 7) + 1;
    const float dy = p.v - float(y0 + ly);
    const int row = ly * kT;
    for (int lx = c0; lx < c1; ++lx) {
      const int k = row + lx;
      const float dx = p.u - float(x0 + lx);
      const float power = -0.5f * (p.a * dx * dx + p.c * dy * dy) - p.b * dx * dy;
      const float g_exp = fast_exp(power);
      const float raw = p.opacity * g_exp;
      const float alpha = std::min(kMaxAlpha, raw);
      const bool valid = (j < s.last[k]) & (power <= 0) & (power >= p.log_cut) & (alpha >= min_alpha);
      const float m = valid ? 1.0f : 0.0f;
      const float Tj = s.T[k] / (1 - alpha);
      const float wj = m * alpha * Tj;
      const float d_alpha = ((p.r0 - s.A0[k]) * s.G0[k] + (p.r1 - s.A1[k]) * s.G1[k] + (p.r2 - s.A2[k]) * s.G2[k] +
                             (p.z - s.AD[k]) * s.GD[k] + (1 - s.AA[k]) * s.GA[k]) * Tj * m;
      const float free = raw < kMaxAlpha ? 1.0f : 0.0f;  // clamped: flat in opacity and position
      const float d_power = d_alpha * raw * free;
      d0 += wj * s.G0[k];
      d1 += wj * s.G1[k];
      d2 += wj * s.G2[k];
      d9 += wj * s.GD[k];
      d3 += d_alpha * g_exp * free;
      d4 += d_power * -(p.a * dx + p.b * dy);
      d5 += d_power * -(p.b * dx + p.c * dy);
      d6 += d_power * -0.5f * dx * dx;
      d7 += d_power * -dx * dy;
      d8 += d_power * -0.5f * dy * dy;
      n += m;
      const float keep = 1 - m * alpha;
      s.A0[k] = m * alpha * p.r0 + keep * s.A0[k];
      s.A1[k] = m * alpha * p.r1 + keep * s.A1[k];
      s.A2[k] = m * alpha * p.r2 + keep * s.A2[k];
      s.AD[k] = m * alpha * p.z + keep * s.AD[k];
      s.AA[k] = m * alpha + keep * s.AA[k];
      s.T[k] = valid ? Tj : s.T[k];
    }
  }
  out[0] = d0, out[1] = d1, out[2] = d2, out[3] = d3, out[4] = d4, out[5] = d5, out[6] = d6, out[7] = d7, out[8] = d8, out[9] = d9;
  return n > 0;
}

}  // namespace

Eigen::Matrix3f quaternion_matrix(float w, float x, float y, float z) {
  Eigen::Matrix3f r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
       2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
       2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

void GsGrads::reset(size_t n, size_t sky_texels) {
  gaussians.assign(n * kParamCount, 0.0f);
  sky.assign(sky_texels * 3, 0.0f);
  pose.setZero();
  screen.assign(n, 0.0f);
  visible.assign(n, 0);
}

GsImage Rasterizer::forward(const Gaussians& g, const SkyTexture* sky, const GsView& v) {
  view_ = v;
  const size_t n = g.size();
  proj_.resize(n);
  vis_.assign(n, 0);
  tiles_x_ = (v.width + kTile - 1) / kTile;
  tiles_y_ = (v.height + kTile - 1) / kTile;
  const int n_tiles = tiles_x_ * tiles_y_;
  // 1. Project every Gaussian.
  const int chunk = 4096;
  parallel_for(int((n + chunk - 1) / chunk), [&](int ci) {
    const size_t end = std::min(n, size_t(ci + 1) * chunk);
    for (size_t i = size_t(ci) * chunk; i < end; ++i) {
      const float* gp = g.at(i);
      Footprint f;
      if (!footprint(gp, v, near_m, f)) continue;
      Proj& p = proj_[i];
      const float det = f.A * f.C - f.B * f.B;
      p.a = f.C / det, p.b = -f.B / det, p.c = f.A / det;
      p.opacity = sigmoid(gp[kOpacity]);
      // Reach: where the weight falls below min_alpha, at most extent_sigma deviations.
      const float reach2 = std::min(extent_sigma * extent_sigma, -2.0f * std::log(min_alpha / std::max(p.opacity, 1e-12f)));
      if (!(reach2 > 0)) continue;
      p.log_cut = -0.5f * reach2;
      // The box around the ellipse d^T S^-1 d = reach2 (S = [[A, B], [B, C]]): tighter than a
      // square of the longest axis for a tilted, elongated footprint (23-33 % fewer tile entries).
      p.rx = std::sqrt(reach2 * f.A), p.ry = std::sqrt(reach2 * f.C);
      p.u = v.fx * f.p.x() / f.p.z() + v.cx;
      p.v = v.fy * f.p.y() / f.p.z() + v.cy;
      p.z = f.p.z();
      if (p.u + p.rx < -0.5f || p.u - p.rx > float(v.width) - 0.5f || p.v + p.ry < -0.5f || p.v - p.ry > float(v.height) - 0.5f)
        continue;
      for (int c = 0; c < 3; ++c) {
        const float* k = gp + kColor + 4 * c;
        p.rgb[c] = std::exp(clamp_log(k[0] + k[1] * f.dir.x() + k[2] * f.dir.y() + k[3] * f.dir.z()));
      }
      vis_[i] = 1;
    }
  }, threads);
  // 2. Bin into tiles, sorted by depth within each tile.
  std::vector<uint32_t> count(size_t(n_tiles) + 1, 0);
  auto tile_rect = [&](const Proj& p, int& x0, int& y0, int& x1, int& y1) {
    x0 = std::max(0, int(std::floor((p.u - p.rx + 0.5f) / kTile)));
    x1 = std::min(tiles_x_ - 1, int(std::floor((p.u + p.rx + 0.5f) / kTile)));
    y0 = std::max(0, int(std::floor((p.v - p.ry + 0.5f) / kTile)));
    y1 = std::min(tiles_y_ - 1, int(std::floor((p.v + p.ry + 0.5f) / kTile)));
  };
  visible_ = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!vis_[i]) continue;
    ++visible_;
    int x0, y0, x1, y1;
    tile_rect(proj_[i], x0, y0, x1, y1);
    for (int ty = y0; ty <= y1; ++ty)
      for (int tx = x0; tx <= x1; ++tx) ++count[size_t(ty * tiles_x_ + tx) + 1];
  }
  tile_start_.assign(size_t(n_tiles) + 1, 0);
  for (int t = 0; t < n_tiles; ++t) tile_start_[size_t(t) + 1] = tile_start_[size_t(t)] + count[size_t(t) + 1];
  tile_ids_.resize(tile_start_.back());
  std::vector<uint32_t> fill(tile_start_.begin(), tile_start_.end() - 1);
  for (size_t i = 0; i < n; ++i) {
    if (!vis_[i]) continue;
    int x0, y0, x1, y1;
    tile_rect(proj_[i], x0, y0, x1, y1);
    for (int ty = y0; ty <= y1; ++ty)
      for (int tx = x0; tx <= x1; ++tx) tile_ids_[fill[size_t(ty * tiles_x_ + tx)]++] = uint32_t(i);
  }
  parallel_for(n_tiles, [&](int t) {
    auto b = tile_ids_.begin() + tile_start_[size_t(t)], e = tile_ids_.begin() + tile_start_[size_t(t) + 1];
    std::sort(b, e, [&](uint32_t x, uint32_t y) { return proj_[x].z < proj_[y].z || (proj_[x].z == proj_[y].z && x < y); });
  }, threads);
  // 3. Composite each tile front to back, one Gaussian at a time over the pixels it reaches
  // (a Gaussian-major loop: contiguous per-pixel state, no work outside its footprint).
  GsImage out;
  out.radiance = cv::Mat(v.height, v.width, CV_32FC3);
  out.depth = cv::Mat(v.height, v.width, CV_32FC1);
  out.alpha = cv::Mat(v.height, v.width, CV_32FC1);
  final_t_ = cv::Mat(v.height, v.width, CV_32FC1);
  n_contrib_ = cv::Mat(v.height, v.width, CV_32SC1);
  static_assert(kTile == kT);
  parallel_for(n_tiles, [&](int t) {
    const int tx = t % tiles_x_, ty = t / tiles_x_;
    const int x0 = tx * kTile, y0 = ty * kTile;
    const int w = std::min(kTile, v.width - x0), h = std::min(kTile, v.height - y0);
    const uint32_t s0 = tile_start_[size_t(t)], s1 = tile_start_[size_t(t) + 1];
    TileState st;
    for (int k = 0; k < kPix; ++k) {
      st.T[k] = 1, st.C0[k] = st.C1[k] = st.C2[k] = st.D[k] = st.last[k] = st.done[k] = 0;
      st.inside[k] = (k % kT < w && k / kT < h) ? 1.0f : 0.0f;
    }
    for (uint32_t j = s0; j < s1; ++j) {
      const Proj& p = proj_[tile_ids_[j]];
      const int py0 = std::max(0, int(std::floor(p.v - p.ry)) - y0), py1 = std::min(h - 1, int(std::ceil(p.v + p.ry)) - y0);
      const int px0 = std::max(0, int(std::floor(p.u - p.rx)) - x0), px1 = std::min(w - 1, int(std::ceil(p.u + p.rx)) - x0);
      if (py0 > py1 || px0 > px1) continue;
      blend_rows(st, ProjView{p.u, p.v, p.z, p.a, p.b, p.c, p.opacity, p.log_cut, p.rgb[0], p.rgb[1], p.rgb[2]}, x0, y0,
                 px0, px1, py0, py1, float(j - s0 + 1), min_alpha);
      if ((j - s0) % 32 == 31) {  // every pixel saturated: nothing behind can show
        float open = 0;
        for (int k = 0; k < kPix; ++k) open += st.inside[k] * (1 - st.done[k]);
        if (open == 0) break;
      }
    }
    for (int ly = 0; ly < h; ++ly)
      for (int lx = 0; lx < w; ++lx) {
        const int k = ly * kTile + lx, x = x0 + lx, y = y0 + ly;
        float c[3] = {st.C0[k], st.C1[k], st.C2[k]};
        if (sky != nullptr) {
          const Eigen::Vector3f dir =
              (v.rotation * Eigen::Vector3f((float(x) - v.cx) / v.fx, (float(y) - v.cy) / v.fy, 1)).normalized();
          const Eigen::Vector3f b = sky->radiance(dir);
          for (int ch = 0; ch < 3; ++ch) c[ch] += st.T[k] * b[ch];
        }
        out.radiance.at<cv::Vec3f>(y, x) = {c[0], c[1], c[2]};
        out.depth.at<float>(y, x) = st.D[k];
        out.alpha.at<float>(y, x) = 1 - st.T[k];
        final_t_.at<float>(y, x) = st.T[k];
        n_contrib_.at<int>(y, x) = int(st.last[k]);
      }
  }, threads);
  return out;
}

void Rasterizer::backward(const Gaussians& g, const SkyTexture* sky, const cv::Mat& d_rad, const cv::Mat& d_depth,
                          const cv::Mat& d_alpha, GsGrads& grads) {
  const GsView& v = view_;
  const size_t n = g.size();
  const int workers = threads > 0 ? threads : default_threads();
  // Per worker: d/d(rgb[3], opacity, u, v, conic a, b, c, z) per Gaussian, sky and pose partials.
  constexpr int kPartial = 10;
  // Kept between calls: training calls this every iteration, and these buffers (tens of MB)
  // allocated afresh each time came as fresh pages from the system (page faults).
  auto& part = part_;
  auto& sky_part = sky_part_;
  part.resize(size_t(workers));
  for (auto& p : part) p.assign(n * kPartial, 0.0f);
  sky_part.resize(size_t(workers));
  for (auto& s : sky_part) s.assign(sky != nullptr ? sky->data().size() : 0, 0.0f);
  const int n_tiles = tiles_x_ * tiles_y_;
  const bool has_depth = !d_depth.empty(), has_alpha = !d_alpha.empty();
  // Static: each worker's partial sums cover the same tiles on every run (reproducible training).
  parallel_for_workers_static(n_tiles, workers, [&](int t, int wk) {
    float* P = part[size_t(wk)].data();
    const int tx = t % tiles_x_, ty = t / tiles_x_;
    const int x0 = tx * kTile, y0 = ty * kTile;
    const int w = std::min(kTile, v.width - x0), h = std::min(kTile, v.height - y0);
    const uint32_t s0 = tile_start_[size_t(t)];
    BackState st;
    int max_last = 0;
    for (int k = 0; k < kPix; ++k) {
      st.G0[k] = st.G1[k] = st.G2[k] = st.GD[k] = st.GA[k] = 0;
      st.A0[k] = st.A1[k] = st.A2[k] = st.AD[k] = st.AA[k] = 0;
      st.T[k] = 1, st.last[k] = 0;
    }
    for (int ly = 0; ly < h; ++ly)
      for (int lx = 0; lx < w; ++lx) {
        const int k = ly * kTile + lx, x = x0 + lx, y = y0 + ly;
        const cv::Vec3f g = d_rad.at<cv::Vec3f>(y, x);
        st.G0[k] = g[0], st.G1[k] = g[1], st.G2[k] = g[2];
        st.GD[k] = has_depth ? d_depth.at<float>(y, x) : 0.0f;
        st.GA[k] = has_alpha ? d_alpha.at<float>(y, x) : 0.0f;
        st.T[k] = final_t_.at<float>(y, x);
        st.last[k] = float(n_contrib_.at<int>(y, x));
        max_last = std::max(max_last, n_contrib_.at<int>(y, x));
        if (sky != nullptr) {
          const Eigen::Vector3f dir =
              (v.rotation * Eigen::Vector3f((float(x) - v.cx) / v.fx, (float(y) - v.cy) / v.fy, 1)).normalized();
          const auto taps = sky->taps(dir);
          const Eigen::Vector3f b = sky->radiance(taps);
          st.A0[k] = b[0], st.A1[k] = b[1], st.A2[k] = b[2];
          sky->backward(taps, Eigen::Vector3f(g[0], g[1], g[2]) * st.T[k], b, sky_part[size_t(wk)].data());
        }
      }
    for (int j = max_last - 1; j >= 0; --j) {
      const uint32_t id = tile_ids_[s0 + uint32_t(j)];
      const Proj& p = proj_[id];
      const int py0 = std::max(0, int(std::floor(p.v - p.ry)) - y0), py1 = std::min(h - 1, int(std::ceil(p.v + p.ry)) - y0);
      const int px0 = std::max(0, int(std::floor(p.u - p.rx)) - x0), px1 = std::min(w - 1, int(std::ceil(p.u + p.rx)) - x0);
      if (py0 > py1 || px0 > px1) continue;
      float d[kPartial];
      if (!unblend_rows(st, ProjView{p.u, p.v, p.z, p.a, p.b, p.c, p.opacity, p.log_cut, p.rgb[0], p.rgb[1], p.rgb[2]}, x0, y0,
                        px0, px1, py0, py1, float(j), min_alpha, d))
        continue;
      float* pp = P + size_t(id) * kPartial;
      for (int k = 0; k < kPartial; ++k) pp[k] += d[k];
    }
  });
  // Sum the workers' partials and carry them back to the parameters.
  if (sky != nullptr)
    for (const auto& s : sky_part)
      for (size_t k = 0; k < s.size(); ++k) grads.sky[k] += s[k];
  std::vector<Eigen::Matrix<float, 6, 1>> pose_part(size_t(workers), Eigen::Matrix<float, 6, 1>::Zero());
  const int chunk = 4096;
  parallel_for_workers_static(int((n + chunk - 1) / chunk), workers, [&](int ci, int w) {
    const size_t end = std::min(n, size_t(ci + 1) * chunk);
    for (size_t i = size_t(ci) * chunk; i < end; ++i) {
      if (!vis_[i]) continue;
      float d[kPartial] = {0};
      for (const auto& pw : part)
        for (int k = 0; k < kPartial; ++k) d[k] += pw[i * kPartial + size_t(k)];
      const float* gp = g.at(i);
      float* out = &grads.gaussians[i * kParamCount];
      grads.visible[i] = 1;
      Footprint f;
      if (!footprint(gp, v, near_m, f)) continue;
      const Proj& p = proj_[i];
      // Colour: rgb = exp(k0 + k . dir), dir = (mu - centre) / |mu - centre|.
      Eigen::Vector3f d_dir = Eigen::Vector3f::Zero();
      for (int c = 0; c < 3; ++c) {
        const float* k = gp + kColor + 4 * c;
        const float l = k[0] + k[1] * f.dir.x() + k[2] * f.dir.y() + k[3] * f.dir.z();
        const float dl = l > kMaxLogRadiance ? 0.0f : d[c] * p.rgb[c];
        out[kColor + 4 * c] += dl;
        out[kColor + 4 * c + 1] += dl * f.dir.x();
        out[kColor + 4 * c + 2] += dl * f.dir.y();
        out[kColor + 4 * c + 3] += dl * f.dir.z();
        d_dir += dl * Eigen::Vector3f(k[1], k[2], k[3]);
      }
      const Eigen::Vector3f d_mu_dir =
          (Eigen::Matrix3f::Identity() - f.dir * f.dir.transpose()) * d_dir / (Eigen::Vector3f(gp[kPosX], gp[kPosY], gp[kPosZ]) - v.center).norm();
      out[kOpacity] += d[3] * p.opacity * (1 - p.opacity);
      // Conic (inverse of [[A, B], [B, C]]) back to the 2D covariance: dS = -M dM M.
      const Eigen::Matrix2f M = (Eigen::Matrix2f() << p.a, p.b, p.b, p.c).finished();
      const Eigen::Matrix2f dM = (Eigen::Matrix2f() << d[6], 0.5f * d[7], 0.5f * d[7], d[8]).finished();
      const Eigen::Matrix2f dS = -M * dM * M;
      // S = J Sc J^T: back to the camera covariance and the Jacobian.
      const Eigen::Matrix3f dSc = f.jac.transpose() * dS * f.jac;
      const Eigen::Matrix<float, 2, 3> dJ = 2.0f * dS * f.jac * f.cov_cam;
      // Sc = W S3 W^T, S3 = (R S)(R S)^T.
      const Eigen::Matrix3f W = v.rotation.transpose();
      const Eigen::Matrix3f dS3 = W.transpose() * dSc * W;
      const Eigen::Matrix3f Mrs = f.rot * f.scale.asDiagonal();
      const Eigen::Matrix3f dMrs = 2.0f * dS3 * Mrs;
      for (int k = 0; k < 3; ++k) out[kScaleX + k] += f.rot.col(k).dot(dMrs.col(k)) * f.scale[k];
      const Eigen::Matrix3f dR = dMrs * f.scale.asDiagonal();
      const float qw = f.qn[0], qx = f.qn[1], qy = f.qn[2], qz = f.qn[3];
      Eigen::Matrix3f Rw, Rx, Ry, Rz;
      Rw << 0, -2 * qz, 2 * qy, 2 * qz, 0, -2 * qx, -2 * qy, 2 * qx, 0;
      Rx << 0, 2 * qy, 2 * qz, 2 * qy, -4 * qx, -2 * qw, 2 * qz, 2 * qw, -4 * qx;
      Ry << -4 * qy, 2 * qx, 2 * qw, 2 * qx, 0, 2 * qz, -2 * qw, 2 * qz, -4 * qy;
      Rz << -4 * qz, -2 * qw, 2 * qx, 2 * qw, -4 * qz, 2 * qy, 2 * qx, 2 * qy, 0;
      const Eigen::Vector4f dqn(dR.cwiseProduct(Rw).sum(), dR.cwiseProduct(Rx).sum(), dR.cwiseProduct(Ry).sum(),
                                dR.cwiseProduct(Rz).sum());
      const Eigen::Vector4f qv(qw, qx, qy, qz);
      const Eigen::Vector4f dq = (dqn - qv * qv.dot(dqn)) / f.qnorm;
      for (int k = 0; k < 4; ++k) out[kRotW + k] += dq[k];
      // Camera-frame position: through the pixel position, the Jacobian and the depth.
      const float z = f.p.z(), z2 = z * z;
      Eigen::Vector3f dp = Eigen::Vector3f::Zero();
      dp.x() += d[4] * v.fx / z;
      dp.y() += d[5] * v.fy / z;
      dp.z() += -d[4] * v.fx * f.p.x() / z2 - d[5] * v.fy * f.p.y() / z2;
      // J = [[fx/z, 0, -fx tx/z], [0, fy/z, -fy ty/z]] with tx = x/z (unless clamped).
      dp.z() += dJ(0, 0) * -v.fx / z2 + dJ(1, 1) * -v.fy / z2;
      if (f.clamped_x) dp.z() += dJ(0, 2) * v.fx * f.tx / z2;
      else dp.x() += dJ(0, 2) * -v.fx / z2, dp.z() += dJ(0, 2) * 2 * v.fx * f.p.x() / (z2 * z);
      if (f.clamped_y) dp.z() += dJ(1, 2) * v.fy * f.ty / z2;
      else dp.y() += dJ(1, 2) * -v.fy / z2, dp.z() += dJ(1, 2) * 2 * v.fy * f.p.y() / (z2 * z);
      dp.z() += d[9];
      const Eigen::Vector3f dmu = W.transpose() * dp + d_mu_dir;
      out[kPosX] += dmu.x(), out[kPosY] += dmu.y(), out[kPosZ] += dmu.z();
      // Densification signal: the screen-space gradient in NDC units.
      grads.screen[i] += std::sqrt(d[4] * d[4] * 0.25f * float(v.width * v.width) + d[5] * d[5] * 0.25f * float(v.height * v.height)) ;
      if (pose_blind != nullptr && (*pose_blind)[i]) continue;
      // Camera twist (w, t) in the camera frame: p' = exp(-w) (p - t), so dp'/dw = [p]x and
      // dp'/dt = -I; the camera covariance turns with it (Sc' = Sc - [w]x Sc + Sc [w]x); the
      // view direction moves with the centre.
      auto& pose = pose_part[size_t(w)];
      pose.head<3>() += dp.cross(f.p);
      for (int k = 0; k < 3; ++k) {
        Eigen::Matrix3f e = Eigen::Matrix3f::Zero();
        const Eigen::Vector3f axis = Eigen::Vector3f::Unit(k);
        e << 0, -axis.z(), axis.y(), axis.z(), 0, -axis.x(), -axis.y(), axis.x(), 0;
        pose[k] += dSc.cwiseProduct(f.cov_cam * e - e * f.cov_cam).sum();
      }
      pose.tail<3>() += -dp - W * d_mu_dir;
    }
  });
  for (const auto& pp : pose_part) grads.pose += pp;
}

}  // namespace chatsim::render::gs
