#pragma once
// An HDR environment (equirectangular, render/equirect.hpp) that lights a scene, with
// importance sampling proportional to luminance x solid angle.
#include <filesystem>
#include <vector>

#include "render/color.hpp"

namespace chatsim::render {

class EnvMap {
 public:
  EnvMap() = default;
  EnvMap(int width, int height, std::vector<Rgb> pixels);  // row-major, row 0 at the zenith
  static EnvMap uniform(const Rgb& radiance, int width = 64, int height = 32);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return pixels_.empty(); }
  const std::vector<Rgb>& pixels() const { return pixels_; }
  Rgb& at(int x, int y) { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
  const Rgb& at(int x, int y) const { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }

  // Radiance arriving from direction d (world, unit), bilinear.
  Rgb radiance(const Eigen::Vector3f& d) const;
  // A direction drawn in proportion to luminance, and its solid-angle pdf.
  Eigen::Vector3f sample(float u1, float u2, float* pdf) const;
  float pdf(const Eigen::Vector3f& d) const;
  // Irradiance on a surface with normal n from the whole map (numerical integral).
  Rgb irradiance(const Eigen::Vector3f& n) const;
  // Call after editing pixels through at(): rebuilds the sampling tables.
  void update();

  void write_exr(const std::filesystem::path& file) const;
  static EnvMap read(const std::filesystem::path& file);  // EXR or Radiance HDR

 private:
  int width_ = 0, height_ = 0;
  std::vector<Rgb> pixels_;
  std::vector<float> marginal_cdf_;     // height + 1
  std::vector<float> conditional_cdf_;  // height x (width + 1)
  std::vector<float> row_weight_;       // height
  float total_ = 0;
};

}  // namespace chatsim::render
