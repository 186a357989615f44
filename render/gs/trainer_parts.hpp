#pragma once
// The trainer's parts (not an API): training images, the optimiser and pose parameters, and
// how the Gaussians are seeded. trainer.cpp trains; trainer_setup.cpp loads and seeds.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "common/scene/scene.hpp"
#include "render/gs/gaussians.hpp"
#include "render/gs/trainer.hpp"

namespace chatsim::render::gs::detail {

struct TrainImage {
  int frame = 0;
  std::string camera;
  scene::Camera cam;
  Eigen::Isometry3d pose;     // recorded
  cv::Mat rgb;                // CV_8UC3 at training resolution
  double exposure = 1.0;      // known exposure (1: unknown or not used)
  double time = 0;
  std::vector<Eigen::Vector3f> lidar;  // world points this image sees (depth supervision)
};

inline double oetf_slope(double x) { return x <= 0.0031308 ? 12.92 : 1.055 / 2.4 * std::pow(x, 1.0 / 2.4 - 1.0); }

// The OETF and its slope on [0, 1] by table (the loss evaluates them for every pixel).
class OetfTable {
 public:
  static constexpr int kSize = 8192;
  OetfTable() {
    for (int i = 0; i <= kSize; ++i) {
      const double x = double(i) / kSize;
      value_[size_t(i)] = srgb_oetf(float(x));
      slope_[size_t(i)] = float(oetf_slope(std::max(x, 1e-6)));
    }
  }
  // Linear interpolation of the value; the slope of the cell (exact derivative of that line).
  void eval(double lin, double& value, double& slope) const {
    if (lin >= 1) {
      value = 1.0 + slope_[kSize] * (lin - 1);  // continued linearly above 1
      slope = slope_[kSize];
      return;
    }
    const double f = std::max(lin, 0.0) * kSize;
    const int i = std::min(int(f), kSize - 1);
    const double a = f - i;
    value = value_[size_t(i)] * (1 - a) + value_[size_t(i) + 1] * a;
    slope = lin <= 0 ? slope_[0] : (value_[size_t(i) + 1] - value_[size_t(i)]) * kSize;
  }

 private:
  std::array<float, kSize + 1> value_, slope_;
};

// Adam over a flat parameter array with a learning rate per slot of a record.
class Adam {
 public:
  void resize(size_t n) { m_.resize(n, 0.0f), v_.resize(n, 0.0f); }
  void step(float* p, const float* g, size_t n, const float* lr, size_t record, int t) {
    const float b1 = 0.9f, b2 = 0.999f;
    const float c1 = 1 - std::pow(b1, float(t)), c2 = 1 - std::pow(b2, float(t));
    for (size_t i = 0; i < n; ++i) {
      if (g[i] == 0.0f) continue;  // untouched this step (not in view): keep its moments
      m_[i] = b1 * m_[i] + (1 - b1) * g[i];
      v_[i] = b2 * v_[i] + (1 - b2) * g[i] * g[i];
      p[i] -= lr[i % record] * (m_[i] / c1) / (std::sqrt(v_[i] / c2) + 1e-8f);
    }
  }
  std::vector<float>& m() { return m_; }
  std::vector<float>& v() { return v_; }

 private:
  std::vector<float> m_, v_;
};

// A 6-vector twist optimised with Adam, applied as a right-multiplied correction.
struct TwistParam {
  PoseCorrection* target = nullptr;
  float m[6] = {0}, v[6] = {0};
  int t = 0;
  void step(const Eigen::Matrix<float, 6, 1>& g, float lr_rot, float lr_trans) {
    ++t;
    const float c1 = 1 - std::pow(0.9f, float(t)), c2 = 1 - std::pow(0.999f, float(t));
    Eigen::Matrix<float, 6, 1> d;
    for (int k = 0; k < 6; ++k) {
      m[k] = 0.9f * m[k] + 0.1f * g[k];
      v[k] = 0.999f * v[k] + 0.001f * g[k] * g[k];
      d[k] = -(k < 3 ? lr_rot : lr_trans) * (m[k] / c1) / (std::sqrt(v[k] / c2) + 1e-12f);
    }
    // Compose: T <- T * exp(d).
    PoseCorrection inc;
    inc.rotation = d.head<3>();
    inc.translation = d.tail<3>();
    const Eigen::Isometry3d T = target->transform() * inc.transform();
    const Eigen::AngleAxisd aa(T.linear());
    target->rotation = (aa.axis() * aa.angle()).cast<float>();
    target->translation = T.translation().cast<float>();
  }
};

std::vector<TrainImage> load_images(const scene::Scene& s, const TrainOptions& o, int max_width, int* held);

// The box of object k at frame f (world to object), or none.
std::optional<Eigen::Isometry3d> box_inverse(const scene::Scene& s, size_t k, int frame);

// LiDAR points of each image's frame, placed at the image's time (points on a labelled object
// move with it), a sample of those in front of the camera: they supervise rendered depth.
void attach_lidar(const scene::Scene& s, std::vector<TrainImage>& images, uint64_t seed);

struct Seed {
  Eigen::Vector3f position;  // world (background) or object frame
  float sigma;
  int owner;
  int frame;                 // where it was seen (objects: to find its colour)
  Eigen::Vector3f world;     // world position at that frame
};

Eigen::Vector3f seed_colour(const std::vector<TrainImage>& images, const Seed& s, float fallback);

std::vector<Seed> lidar_seeds(const scene::Scene& s, const std::vector<Eigen::Vector3d>& path);

// Above the LiDAR's highest beam the facades go on: per image, a column of 8 x 8 cells keeps
// the depth of the highest cell the LiDAR reached (a vertical surface keeps its camera depth
// up a column). Where that guess is sky, training makes those Gaussians transparent.
std::vector<Seed> facade_seeds(const scene::Scene& s, const std::vector<TrainImage>& images);

bool inside_box(const Eigen::Vector3d& local, const Eigen::Vector3d& size, double margin);

// Background seeds that fall inside a labelled box at their frame belong to that object (the
// facades' upward guess lands on cars too): otherwise hiding the object would leave them.
void assign_seeds_to_objects(const scene::Scene& s, std::vector<Seed>& seeds);

// Objects that never move: their boxes are fixed in the world.
std::vector<std::optional<Eigen::Isometry3d>> static_boxes(const scene::Scene& s);

// Background Gaussians that drifted into a parked object's box join the object (its frame).
int adopt_into_static_objects(Gaussians& g, std::vector<int>& owner, const scene::Scene& s,
                              const std::vector<std::optional<Eigen::Isometry3d>>& boxes);

}  // namespace chatsim::render::gs::detail
