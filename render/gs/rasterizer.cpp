#include "render/gs/rasterizer.hpp"

#include <algorithm>
#include <cmath>

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
      const float mid = 0.5f * (f.A + f.C);
      const float lambda = mid + std::sqrt(std::max(0.1f, mid * mid - det));
      p.opacity = sigmoid(gp[kOpacity]);
      // Reach: where the weight falls below min_alpha, at most extent_sigma deviations.
      p.log_cut = std::log(min_alpha / std::max(p.opacity, 1e-12f));
      const float reach2 = std::min(extent_sigma * extent_sigma, std::max(0.0f, -2.0f * p.log_cut));
      if (reach2 <= 0) continue;
      p.radius = int(std::ceil(std::sqrt(reach2 * lambda)));
      p.u = v.fx * f.p.x() / f.p.z() + v.cx;
      p.v = v.fy * f.p.y() / f.p.z() + v.cy;
      p.z = f.p.z();
      if (p.u + float(p.radius) < -0.5f || p.u - float(p.radius) > float(v.width) - 0.5f ||
          p.v + float(p.radius) < -0.5f || p.v - float(p.radius) > float(v.height) - 0.5f)
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
    x0 = std::max(0, int(std::floor((p.u - float(p.radius) + 0.5f) / kTile)));
    x1 = std::min(tiles_x_ - 1, int(std::floor((p.u + float(p.radius) + 0.5f) / kTile)));
    y0 = std::max(0, int(std::floor((p.v - float(p.radius) + 0.5f) / kTile)));
    y1 = std::min(tiles_y_ - 1, int(std::floor((p.v + float(p.radius) + 0.5f) / kTile)));
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
  parallel_for(n_tiles, [&](int t) {
    const int tx = t % tiles_x_, ty = t / tiles_x_;
    const int x0 = tx * kTile, y0 = ty * kTile;
    const int w = std::min(kTile, v.width - x0), h = std::min(kTile, v.height - y0);
    const uint32_t s0 = tile_start_[size_t(t)], s1 = tile_start_[size_t(t) + 1];
    float T[kTile * kTile], C[3][kTile * kTile], D[kTile * kTile];
    int last[kTile * kTile];
    bool done[kTile * kTile];
    for (int k = 0; k < kTile * kTile; ++k) T[k] = 1, C[0][k] = C[1][k] = C[2][k] = D[k] = 0, last[k] = 0, done[k] = false;
    int active = w * h;
    for (uint32_t j = s0; j < s1 && active > 0; ++j) {
      const Proj& p = proj_[tile_ids_[j]];
      const int px0 = std::max(0, int(std::floor(p.u - float(p.radius))) - x0), px1 = std::min(w - 1, int(std::ceil(p.u + float(p.radius))) - x0);
      const int py0 = std::max(0, int(std::floor(p.v - float(p.radius))) - y0), py1 = std::min(h - 1, int(std::ceil(p.v + float(p.radius))) - y0);
      for (int ly = py0; ly <= py1; ++ly) {
        const float dy = p.v - float(y0 + ly);
        for (int lx = px0; lx <= px1; ++lx) {
          const int k = ly * kTile + lx;
          if (done[k]) continue;
          const float dx = p.u - float(x0 + lx);
          const float power = -0.5f * (p.a * dx * dx + p.c * dy * dy) - p.b * dx * dy;
          if (power > 0 || power < p.log_cut) continue;
          const float alpha = std::min(kMaxAlpha, p.opacity * std::exp(power));
          if (alpha < min_alpha) continue;
          const float test_t = T[k] * (1 - alpha);
          if (test_t < kMinTransmittance) {
            done[k] = true;
            --active;
            continue;
          }
          const float wgt = alpha * T[k];
          C[0][k] += wgt * p.rgb[0], C[1][k] += wgt * p.rgb[1], C[2][k] += wgt * p.rgb[2];
          D[k] += wgt * p.z;
          T[k] = test_t;
          last[k] = int(j - s0) + 1;
        }
      }
    }
    for (int ly = 0; ly < h; ++ly)
      for (int lx = 0; lx < w; ++lx) {
        const int k = ly * kTile + lx, x = x0 + lx, y = y0 + ly;
        float c[3] = {C[0][k], C[1][k], C[2][k]};
        if (sky != nullptr) {
          const Eigen::Vector3f dir =
              (v.rotation * Eigen::Vector3f((float(x) - v.cx) / v.fx, (float(y) - v.cy) / v.fy, 1)).normalized();
          const Eigen::Vector3f b = sky->radiance(dir);
          for (int ch = 0; ch < 3; ++ch) c[ch] += T[k] * b[ch];
        }
        out.radiance.at<cv::Vec3f>(y, x) = {c[0], c[1], c[2]};
        out.depth.at<float>(y, x) = D[k];
        out.alpha.at<float>(y, x) = 1 - T[k];
        final_t_.at<float>(y, x) = T[k];
        n_contrib_.at<int>(y, x) = last[k];
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
  std::vector<std::vector<float>> part(size_t(workers), std::vector<float>(n * kPartial, 0.0f));
  std::vector<std::vector<float>> sky_part{size_t(workers)};
  if (sky != nullptr)
    for (auto& s : sky_part) s.assign(sky->data().size(), 0.0f);
  const int n_tiles = tiles_x_ * tiles_y_;
  const bool has_depth = !d_depth.empty(), has_alpha = !d_alpha.empty();
  parallel_for_workers(n_tiles, workers, [&](int t, int wk) {
    float* P = part[size_t(wk)].data();
    const int tx = t % tiles_x_, ty = t / tiles_x_;
    const int x0 = tx * kTile, y0 = ty * kTile;
    const int w = std::min(kTile, v.width - x0), h = std::min(kTile, v.height - y0);
    const uint32_t s0 = tile_start_[size_t(t)];
    // Per pixel: the loss gradient, and the state walked back from the last contributor.
    float G[3][kTile * kTile], GD[kTile * kTile], GA[kTile * kTile], T[kTile * kTile];
    float acc_c[3][kTile * kTile], acc_d[kTile * kTile], acc_a[kTile * kTile];
    int last[kTile * kTile];
    int max_last = 0;
    for (int k = 0; k < kTile * kTile; ++k) last[k] = 0;
    for (int ly = 0; ly < h; ++ly)
      for (int lx = 0; lx < w; ++lx) {
        const int k = ly * kTile + lx, x = x0 + lx, y = y0 + ly;
        const cv::Vec3f g = d_rad.at<cv::Vec3f>(y, x);
        for (int c = 0; c < 3; ++c) G[c][k] = g[c], acc_c[c][k] = 0;
        GD[k] = has_depth ? d_depth.at<float>(y, x) : 0.0f;
        GA[k] = has_alpha ? d_alpha.at<float>(y, x) : 0.0f;
        T[k] = final_t_.at<float>(y, x);
        acc_d[k] = acc_a[k] = 0;
        last[k] = n_contrib_.at<int>(y, x);
        max_last = std::max(max_last, last[k]);
        if (sky != nullptr) {
          const Eigen::Vector3f dir =
              (v.rotation * Eigen::Vector3f((float(x) - v.cx) / v.fx, (float(y) - v.cy) / v.fy, 1)).normalized();
          const auto taps = sky->taps(dir);
          const Eigen::Vector3f b = sky->radiance(taps);
          for (int c = 0; c < 3; ++c) acc_c[c][k] = b[c];
          sky->backward(taps, Eigen::Vector3f(g[0], g[1], g[2]) * T[k], b, sky_part[size_t(wk)].data());
        }
      }
    for (int j = max_last - 1; j >= 0; --j) {
      const uint32_t id = tile_ids_[s0 + uint32_t(j)];
      const Proj& p = proj_[id];
      const int px0 = std::max(0, int(std::floor(p.u - float(p.radius))) - x0), px1 = std::min(w - 1, int(std::ceil(p.u + float(p.radius))) - x0);
      const int py0 = std::max(0, int(std::floor(p.v - float(p.radius))) - y0), py1 = std::min(h - 1, int(std::ceil(p.v + float(p.radius))) - y0);
      float d[kPartial] = {0};
      bool touched = false;
      for (int ly = py0; ly <= py1; ++ly) {
        const float dy = p.v - float(y0 + ly);
        for (int lx = px0; lx <= px1; ++lx) {
          const int k = ly * kTile + lx;
          if (j >= last[k]) continue;
          const float dx = p.u - float(x0 + lx);
          const float power = -0.5f * (p.a * dx * dx + p.c * dy * dy) - p.b * dx * dy;
          if (power > 0 || power < p.log_cut) continue;
          const float g_exp = std::exp(power);
          const float raw = p.opacity * g_exp;
          const float alpha = std::min(kMaxAlpha, raw);
          if (alpha < min_alpha) continue;
          touched = true;
          const float Tj = T[k] / (1 - alpha);
          const float w_j = alpha * Tj;
          float d_alpha_j = 0;
          for (int c = 0; c < 3; ++c) {
            d[c] += w_j * G[c][k];
            d_alpha_j += (p.rgb[c] - acc_c[c][k]) * G[c][k];
            acc_c[c][k] = alpha * p.rgb[c] + (1 - alpha) * acc_c[c][k];
          }
          d_alpha_j += (p.z - acc_d[k]) * GD[k] + (1 - acc_a[k]) * GA[k];
          d[9] += w_j * GD[k];
          acc_d[k] = alpha * p.z + (1 - alpha) * acc_d[k];
          acc_a[k] = alpha + (1 - alpha) * acc_a[k];
          d_alpha_j *= Tj;
          T[k] = Tj;
          if (raw >= kMaxAlpha) continue;  // clamped: flat in opacity and position
          d[3] += d_alpha_j * g_exp;
          const float d_power = d_alpha_j * raw;
          d[4] += d_power * -(p.a * dx + p.b * dy);
          d[5] += d_power * -(p.b * dx + p.c * dy);
          d[6] += d_power * -0.5f * dx * dx;
          d[7] += d_power * -dx * dy;
          d[8] += d_power * -0.5f * dy * dy;
        }
      }
      if (!touched) continue;
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
  parallel_for_workers(int((n + chunk - 1) / chunk), workers, [&](int ci, int w) {
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
      // Densification signal: the screen-space gradient in NDC units.
      grads.screen[i] += std::sqrt(d[4] * d[4] * 0.25f * float(v.width * v.width) + d[5] * d[5] * 0.25f * float(v.height * v.height)) ;
    }
  });
  for (const auto& pp : pose_part) grads.pose += pp;
}

}  // namespace chatsim::render::gs
