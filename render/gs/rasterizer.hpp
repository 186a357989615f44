#pragma once
// Differentiable tile-based rasterisation of 3D Gaussians on the CPU (after Kerbl et al. 2023,
// "3D Gaussian Splatting"): project, bin into 16 x 16 tiles, sort by depth, alpha-composite
// front to back, then the far field (sky texture) behind. Backward gives gradients for every
// Gaussian parameter, the sky texels and the camera pose (a twist in the camera frame).
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "render/gs/gaussians.hpp"
#include "render/gs/sky_texture.hpp"

namespace chatsim::render::gs {

struct GsView {
  int width = 0, height = 0;
  float fx = 0, fy = 0, cx = 0, cy = 0;      // OpenCV convention: integer pixels are centres
  Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();  // camera (OpenCV axes) to world
  Eigen::Vector3f center = Eigen::Vector3f::Zero();        // camera centre, world
};

struct GsImage {
  cv::Mat radiance;  // CV_32FC3 linear, RGB
  cv::Mat depth;     // CV_32FC1: sum of weight x z (divide by alpha for the expected depth)
  cv::Mat alpha;     // CV_32FC1: opacity of the Gaussians (1 - transmittance to the sky)
};

struct GsGrads {
  std::vector<float> gaussians;      // size() * kParamCount
  std::vector<float> sky;            // texels * 3
  Eigen::Matrix<float, 6, 1> pose;   // d loss / d (rotation, translation) twist, camera frame
  std::vector<float> screen;         // |d loss / d mean2D| in NDC units, per Gaussian (densification)
  std::vector<uint8_t> visible;      // per Gaussian: inside this view
  void reset(size_t gaussians, size_t sky_texels);
};

class Rasterizer {
 public:
  static constexpr int kTile = 16;
  float near_m = 0.2f;
  int threads = 0;
  // Cut-offs that make rendering fast (and the loss slightly discontinuous): weights below
  // min_alpha are skipped, and a Gaussian only reaches extent_sigma standard deviations.
  float min_alpha = 1.0f / 255.0f;
  float extent_sigma = 3.0f;
  // Gaussians (by index; nonzero: left out) whose gradients do not reach the camera pose
  // (backward's grads.pose); their own gradients are unchanged. Null: all reach it.
  const std::vector<uint8_t>* pose_blind = nullptr;

  // Renders; keeps what backward() needs. sky may be null (black far field).
  GsImage forward(const Gaussians& g, const SkyTexture* sky, const GsView& view);
  // Gradients of a loss given d loss / d output (any of depth and alpha may be empty), added
  // into grads (which must be reset() to the model's size).
  void backward(const Gaussians& g, const SkyTexture* sky, const cv::Mat& d_radiance, const cv::Mat& d_depth,
                const cv::Mat& d_alpha, GsGrads& grads);

  size_t visible_count() const { return visible_; }

 private:
  struct Proj {
    float u, v, z;          // pixel position and camera depth
    float a, b, c;          // conic (inverse 2D covariance)
    float opacity;          // sigmoid of the logit
    float log_cut;          // power below which it is cut: weight under min_alpha, or beyond extent_sigma
    float rgb[3];           // linear radiance toward this camera
    float rx, ry;           // half-width and half-height (pixels) of the box around that cut's ellipse
  };
  GsView view_;
  std::vector<Proj> proj_;
  std::vector<uint8_t> vis_;
  std::vector<uint32_t> tile_start_, tile_ids_;   // per tile: [start, start+count) into tile_ids_
  cv::Mat final_t_, n_contrib_;
  std::vector<std::vector<float>> part_, sky_part_;  // backward's per-worker partials
  size_t visible_ = 0;
  int tiles_x_ = 0, tiles_y_ = 0;
};

// The rotation matrix of a quaternion (w, x, y, z), normalised.
Eigen::Matrix3f quaternion_matrix(float w, float x, float y, float z);

}  // namespace chatsim::render::gs
