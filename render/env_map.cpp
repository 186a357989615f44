#include "render/env_map.hpp"

#include <algorithm>
#include <stdexcept>

#include "render/equirect.hpp"
#include "render/image_io.hpp"

namespace chatsim::render {

EnvMap::EnvMap(int width, int height, std::vector<Rgb> pixels)
    : width_(width), height_(height), pixels_(std::move(pixels)) {
  if (width_ <= 0 || height_ <= 0 || pixels_.size() != size_t(width_) * size_t(height_))
    throw std::invalid_argument("EnvMap: pixel count does not match the size");
  update();
}

EnvMap EnvMap::uniform(const Rgb& radiance, int width, int height) {
  return EnvMap(width, height, std::vector<Rgb>(size_t(width) * size_t(height), radiance));
}

void EnvMap::update() {
  // Piecewise-constant 2D distribution over (u, v), each texel weighted by luminance x sin(theta).
  conditional_cdf_.assign(size_t(height_) * size_t(width_ + 1), 0.0f);
  marginal_cdf_.assign(size_t(height_ + 1), 0.0f);
  row_weight_.assign(size_t(height_), 0.0f);
  for (int y = 0; y < height_; ++y) {
    const float s = std::sin(kPi * (y + 0.5f) / height_);
    float* cdf = &conditional_cdf_[size_t(y) * size_t(width_ + 1)];
    for (int x = 0; x < width_; ++x) cdf[x + 1] = cdf[x] + std::max(0.0f, luminance(at(x, y))) * s + 1e-12f;
    row_weight_[size_t(y)] = cdf[width_];
    marginal_cdf_[size_t(y + 1)] = marginal_cdf_[size_t(y)] + cdf[width_];
  }
  total_ = marginal_cdf_.back();
}

Rgb EnvMap::radiance(const Eigen::Vector3f& d) const {
  const Eigen::Vector2f uv = equirect_uv(d);
  const float fx = uv.x() * width_ - 0.5f, fy = uv.y() * height_ - 0.5f;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float ax = fx - x0, ay = fy - y0;
  auto texel = [&](int x, int y) -> const Rgb& {
    x = ((x % width_) + width_) % width_;  // wraps around in u
    y = std::clamp(y, 0, height_ - 1);
    return at(x, y);
  };
  return (texel(x0, y0) * (1 - ax) + texel(x0 + 1, y0) * ax) * (1 - ay) +
         (texel(x0, y0 + 1) * (1 - ax) + texel(x0 + 1, y0 + 1) * ax) * ay;
}

namespace {
// Index i with cdf[i] <= target < cdf[i + 1] in a cdf of n + 1 entries.
int find_interval(const float* cdf, int n, float target) {
  const float* it = std::upper_bound(cdf, cdf + n + 1, target);
  return std::clamp(int(it - cdf) - 1, 0, n - 1);
}
}  // namespace

Eigen::Vector3f EnvMap::sample(float u1, float u2, float* pdf) const {
  const float ty = u1 * total_;
  const int y = find_interval(marginal_cdf_.data(), height_, ty);
  const float* cdf = &conditional_cdf_[size_t(y) * size_t(width_ + 1)];
  const float tx = u2 * row_weight_[size_t(y)];
  const int x = find_interval(cdf, width_, tx);
  // Position inside the texel, reusing what is left of the random numbers.
  const float row_span = marginal_cdf_[size_t(y + 1)] - marginal_cdf_[size_t(y)];
  const float dy = row_span > 0 ? (ty - marginal_cdf_[size_t(y)]) / row_span : 0.5f;
  const float col_span = cdf[x + 1] - cdf[x];
  const float dx = col_span > 0 ? (tx - cdf[x]) / col_span : 0.5f;
  const float u = (x + std::clamp(dx, 0.0f, 0.999f)) / width_;
  const float v = (y + std::clamp(dy, 0.0f, 0.999f)) / height_;
  const Eigen::Vector3f d = equirect_dir(u, v);
  if (pdf != nullptr) *pdf = this->pdf(d);
  return d;
}

float EnvMap::pdf(const Eigen::Vector3f& d) const {
  if (total_ <= 0) return 0;
  const Eigen::Vector2f uv = equirect_uv(d);
  const int x = std::clamp(int(uv.x() * width_), 0, width_ - 1);
  const int y = std::clamp(int(uv.y() * height_), 0, height_ - 1);
  const float* cdf = &conditional_cdf_[size_t(y) * size_t(width_ + 1)];
  const float p_texel = (cdf[x + 1] - cdf[x]) / total_;
  const float s = std::sin(kPi * (y + 0.5f) / height_);
  // Texel probability over its solid angle (2 pi / w) (pi / h) sin(theta).
  return s > 0 ? p_texel * width_ * height_ / (2 * kPi * kPi * s) : 0.0f;
}

Rgb EnvMap::irradiance(const Eigen::Vector3f& n) const {
  Rgb e = Rgb::Zero();
  for (int y = 0; y < height_; ++y) {
    const float v = (y + 0.5f) / height_;
    const float d_omega = (2 * kPi / width_) * (kPi / height_) * std::sin(kPi * v);
    for (int x = 0; x < width_; ++x) {
      const float c = equirect_dir((x + 0.5f) / width_, v).dot(n);
      if (c > 0) e += at(x, y) * (c * d_omega);
    }
  }
  return e;
}

void EnvMap::write_exr(const std::filesystem::path& file) const {
  cv::Mat img(height_, width_, CV_32FC3);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const Rgb& c = at(x, y);
      img.at<cv::Vec3f>(y, x) = {c.x(), c.y(), c.z()};
    }
  render::write_exr(file, img);
}

EnvMap EnvMap::read(const std::filesystem::path& file) {
  const cv::Mat img = read_float_image(file);
  if (img.channels() < 3) throw std::runtime_error(file.string() + ": an environment map needs RGB channels");
  std::vector<Rgb> px(size_t(img.rows) * size_t(img.cols));
  const int c = img.channels();
  for (int y = 0; y < img.rows; ++y) {
    const float* row = img.ptr<float>(y);
    for (int x = 0; x < img.cols; ++x) {
      Rgb v(row[x * c], row[x * c + 1], row[x * c + 2]);
      if (!v.allFinite()) v.setZero();  // a corrupt texel must not poison every sample
      px[size_t(y) * size_t(img.cols) + size_t(x)] = v.cwiseMax(0.0f);
    }
  }
  return EnvMap(img.cols, img.rows, std::move(px));
}

}  // namespace chatsim::render
