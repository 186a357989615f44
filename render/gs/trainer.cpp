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

double oetf_slope(double x) { return x <= 0.0031308 ? 12.92 : 1.055 / 2.4 * std::pow(x, 1.0 / 2.4 - 1.0); }

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

std::vector<TrainImage> load_images(const scene::Scene& s, const TrainOptions& o, int max_width, int* held) {
  std::vector<TrainImage> out;
  *held = 0;
  for (const auto& f : s.frames) {
    if (held_out(f.index, o.holdout)) {
      *held += int(f.images.size());
      continue;
    }
    for (const auto& [name, ref] : f.images) {
      const auto* cam = s.camera(name);
      if (cam == nullptr) continue;
      TrainImage im;
      im.frame = f.index;
      im.camera = name;
      im.cam = scaled_camera(*cam, max_width);
      im.pose = s.camera_to_world(f, *cam);
      im.time = ref.timestamp_s;
      cv::Mat rgb = read_rgb8(s.dir / ref.path);
      if (rgb.cols != im.cam.width || rgb.rows != im.cam.height)
        cv::resize(rgb, rgb, cv::Size(im.cam.width, im.cam.height), 0, 0, cv::INTER_AREA);
      im.rgb = rgb;
      im.exposure = (o.exposure && ref.exposure_s) ? *ref.exposure_s : 1.0;
      out.push_back(std::move(im));
    }
  }
  return out;
}

// The box of object k at frame f (world to object), or none.
std::optional<Eigen::Isometry3d> box_inverse(const scene::Scene& s, size_t k, int frame) {
  const auto p = s.objects[k].at(frame);
  if (!p) return std::nullopt;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = p->center;
  T.linear() = Eigen::AngleAxisd(p->yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T.inverse();
}

// LiDAR points of each image's frame, placed at the image's time (points on a labelled object
// move with it), a sample of those in front of the camera: they supervise rendered depth.
void attach_lidar(const scene::Scene& s, std::vector<TrainImage>& images, uint64_t seed) {
  std::map<int, std::vector<Eigen::Vector3d>> world;
  std::map<int, std::vector<int>> owner;
  for (const auto& f : s.frames) {
    if (f.lidar.empty()) continue;
    std::vector<std::optional<Eigen::Isometry3d>> boxes(s.objects.size());
    for (size_t k = 0; k < s.objects.size(); ++k) boxes[k] = box_inverse(s, k, f.index);
    for (const auto& lp : scene::read_lidar(s.dir / f.lidar)) {
      const Eigen::Vector3d w = f.ego_to_world * lp.xyz.cast<double>();
      int own = -1;
      for (size_t k = 0; k < s.objects.size() && own < 0; ++k)
        if (boxes[k]) {
          const Eigen::Vector3d q = *boxes[k] * w;
          const Eigen::Vector3d h = s.objects[k].size_lwh / 2;
          if (std::abs(q.x()) < h.x() && std::abs(q.y()) < h.y() && std::abs(q.z()) < h.z()) own = int(k);
        }
      world[f.index].push_back(w);
      owner[f.index].push_back(own);
    }
  }
  std::mt19937_64 rng(seed);
  for (auto& im : images) {
    const auto it = world.find(im.frame);
    if (it == world.end()) continue;
    const auto& own = owner[im.frame];
    const scene::Frame* fr = s.frame(im.frame);
    std::vector<Eigen::Vector3f> pts;
    for (size_t i = 0; i < it->second.size(); ++i) {
      Eigen::Vector3d w = it->second[i];
      if (own[i] >= 0) {  // on an object: where the object is at the image's time
        const auto& o = s.objects[size_t(own[i])];
        const auto a = object_pose(s, o, fr->timestamp_s), b = object_pose(s, o, im.time);
        if (!a || !b) continue;
        w = *b * (a->inverse() * w);
      }
      const auto pr = scene::project(im.cam, im.pose, w, 1.0);
      if (!pr || !pr->in_image || pr->depth > 60) continue;
      pts.push_back(w.cast<float>());
    }
    std::shuffle(pts.begin(), pts.end(), rng);
    if (pts.size() > 4000) pts.resize(4000);
    im.lidar = std::move(pts);
  }
}

// --- initialisation ---

struct Seed {
  Eigen::Vector3f position;  // world (background) or object frame
  float sigma;
  int owner;
  int frame;                 // where it was seen (objects: to find its colour)
  Eigen::Vector3f world;     // world position at that frame
};

Eigen::Vector3f seed_colour(const std::vector<TrainImage>& images, const Seed& s, float fallback) {
  for (const auto& im : images) {
    if (im.frame != s.frame) continue;
    const auto pr = scene::project(im.cam, im.pose, s.world.cast<double>());
    if (!pr || !pr->in_image) continue;
    const cv::Vec3b px = im.rgb.at<cv::Vec3b>(std::clamp(int(pr->pixel.y() + 0.5), 0, im.rgb.rows - 1),
                                              std::clamp(int(pr->pixel.x() + 0.5), 0, im.rgb.cols - 1));
    const auto& t = srgb_to_linear_table();
    Eigen::Vector3f l;
    for (int c = 0; c < 3; ++c) l[c] = std::log(std::max(t[px[c]], 1e-3f) / float(im.exposure));
    return l;
  }
  return Eigen::Vector3f::Constant(fallback);
}

std::vector<Seed> lidar_seeds(const scene::Scene& s, const std::vector<Eigen::Vector3d>& path) {
  // Voxel-averaged points, voxels growing with distance from the drive (the cameras resolve
  // less far away); points inside a labelled box become that object's, in its frame.
  struct Cell {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    float size = 0;
    int owner = -1;
    int frame = 0;
    Eigen::Vector3d world = Eigen::Vector3d::Zero();
  };
  std::unordered_map<uint64_t, Cell> cells;
  auto key = [](int level, int owner, const Eigen::Vector3i& v) {
    return (uint64_t(level) << 60) ^ (uint64_t(uint32_t(owner + 1) & 0x3ff) << 50) ^ (uint64_t(uint32_t(v.x()) & 0xffff) << 32) ^
           (uint64_t(uint32_t(v.y()) & 0xffff) << 16) ^ uint64_t(uint32_t(v.z()) & 0xffff);
  };
  for (const auto& f : s.frames) {
    if (f.lidar.empty()) continue;
    std::vector<std::pair<int, Eigen::Isometry3d>> boxes;  // object index, world -> object
    for (size_t k = 0; k < s.objects.size(); ++k)
      if (const auto p = s.objects[k].at(f.index)) {
        Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
        T.translation() = p->center;
        T.linear() = Eigen::AngleAxisd(p->yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        boxes.emplace_back(int(k), T.inverse());
      }
    for (const auto& lp : scene::read_lidar(s.dir / f.lidar)) {
      const Eigen::Vector3d w = f.ego_to_world * lp.xyz.cast<double>();
      int owner = -1;
      Eigen::Vector3d local = w;
      for (const auto& [k, inv] : boxes) {
        const Eigen::Vector3d q = inv * w;
        const Eigen::Vector3d half = s.objects[size_t(k)].size_lwh / 2;
        if (std::abs(q.x()) < half.x() + 0.15 && std::abs(q.y()) < half.y() + 0.15 && q.z() > -half.z() + 0.08 &&
            q.z() < half.z() + 0.1) {
          owner = k;
          local = q;
          break;
        }
      }
      float size = 0.05f;
      int level = 0;
      if (owner < 0) {
        double dist = 1e9;
        for (const auto& p : path) dist = std::min(dist, (p - w).norm());
        size = float(std::clamp(0.006 * dist, 0.04, 0.64));
        level = std::max(0, int(std::ceil(std::log2(size / 0.04f) - 1e-6)));
        size = 0.04f * float(1 << level);
      }
      const Eigen::Vector3i v = (local / size).array().floor().cast<int>();
      Cell& c = cells[key(level, owner, v)];
      if (c.n == 0) c.frame = f.index, c.world = w, c.owner = owner, c.size = size;
      c.sum += local;
      ++c.n;
    }
  }
  std::vector<Seed> out;
  out.reserve(cells.size());
  for (const auto& [k, c] : cells)
    out.push_back({(c.sum / c.n).cast<float>(), c.size * 0.7f, c.owner, c.frame, c.world.cast<float>()});
  std::sort(out.begin(), out.end(), [](const Seed& a, const Seed& b) {  // deterministic order
    return std::tie(a.owner, a.frame, a.position.x(), a.position.y(), a.position.z()) <
           std::tie(b.owner, b.frame, b.position.x(), b.position.y(), b.position.z());
  });
  return out;
}

// Above the LiDAR's highest beam the facades go on: per image, a column of 8 x 8 cells keeps
// the depth of the highest cell the LiDAR reached (a vertical surface keeps its camera depth
// up a column). Where that guess is sky, training makes those Gaussians transparent.
std::vector<Seed> facade_seeds(const scene::Scene& s, const std::vector<TrainImage>& images) {
  std::vector<Seed> out;
  std::map<int, std::vector<Eigen::Vector3d>> points;  // frame -> world points
  for (const auto& f : s.frames)
    if (!f.lidar.empty())
      for (const auto& lp : scene::read_lidar(s.dir / f.lidar)) points[f.index].push_back(f.ego_to_world * lp.xyz.cast<double>());
  const int cell = 8;
  for (size_t i = 0; i < images.size(); i += 2) {
    const auto& im = images[i];
    const auto it = points.find(im.frame);
    if (it == points.end()) continue;
    const int cw = (im.cam.width + cell - 1) / cell, ch = (im.cam.height + cell - 1) / cell;
    std::vector<float> depth(size_t(cw * ch), 0.0f);
    for (const auto& w : it->second) {
      const auto pr = scene::project(im.cam, im.pose, w, 0.5);
      if (!pr || !pr->in_image) continue;
      const int cx = std::clamp(int(pr->pixel.x() + 0.5) / cell, 0, cw - 1), cy = std::clamp(int(pr->pixel.y() + 0.5) / cell, 0, ch - 1);
      float& d = depth[size_t(cy * cw + cx)];
      if (d == 0 || pr->depth < d) d = float(pr->depth);
    }
    for (int x = 0; x < cw; ++x) {
      float carried = 0;
      int carried_rows = 0;
      for (int y = ch - 1; y >= 0; --y) {
        const float d = depth[size_t(y * cw + x)];
        if (d > 0) {
          carried = d, carried_rows = 0;
          continue;
        }
        if (carried <= 0 || ++carried_rows > 40 || carried > 60) continue;
        const Eigen::Vector2d px(x * cell + cell / 2, y * cell + cell / 2);
        const Eigen::Vector3d w = scene::unproject(im.cam, im.pose, px, carried);
        out.push_back({w.cast<float>(), float(cell * carried / im.cam.fx) * 0.7f, -1, im.frame, w.cast<float>()});
      }
    }
  }
  return out;
}


bool inside_box(const Eigen::Vector3d& local, const Eigen::Vector3d& size, double margin) {
  const Eigen::Vector3d h = size / 2;
  return std::abs(local.x()) < h.x() + margin && std::abs(local.y()) < h.y() + margin && local.z() > -h.z() + 0.05 &&
         local.z() < h.z() + margin;
}

// Background seeds that fall inside a labelled box at their frame belong to that object (the
// facades' upward guess lands on cars too): otherwise hiding the object would leave them.
void assign_seeds_to_objects(const scene::Scene& s, std::vector<Seed>& seeds) {
  for (auto& sd : seeds) {
    if (sd.owner >= 0) continue;
    for (size_t k = 0; k < s.objects.size(); ++k) {
      const auto inv = box_inverse(s, k, sd.frame);
      if (!inv) continue;
      const Eigen::Vector3d local = *inv * sd.world.cast<double>();
      if (!inside_box(local, s.objects[k].size_lwh, 0.1)) continue;
      sd.owner = int(k);
      sd.position = local.cast<float>();
      break;
    }
  }
}

// Objects that never move: their boxes are fixed in the world.
std::vector<std::optional<Eigen::Isometry3d>> static_boxes(const scene::Scene& s) {
  std::vector<std::optional<Eigen::Isometry3d>> out(s.objects.size());
  for (size_t k = 0; k < s.objects.size(); ++k) {
    const auto& t = s.objects[k].track;
    if (t.empty()) continue;
    double move = 0;
    for (const auto& p : t) move = std::max(move, (p.center - t.front().center).norm());
    if (move < 0.2) out[k] = box_inverse(s, k, t.front().frame);
  }
  return out;
}

}  // namespace

std::vector<uint8_t> moving_shadow_band(const scene::Scene& s, const std::vector<bool>& moves, const Gaussians& placed,
                                        const std::vector<int>& source, const std::vector<int>& owner, double time_s, double pad_m) {
  std::vector<uint8_t> out(placed.size(), 0);
  const float pad = float(pad_m);
  struct Band {
    Eigen::Isometry3f to_box;  // world to box frame
    Eigen::Vector3f size;
    Eigen::AlignedBox3f world;  // holds the band, for a cheap test first
  };
  std::vector<Band> bands;
  Eigen::AlignedBox3f any;  // holds every band
  for (size_t k = 0; k < s.objects.size() && k < moves.size(); ++k) {
    if (!moves[k]) continue;
    const auto p = object_pose(s, s.objects[k], time_s);
    if (!p) continue;
    const Eigen::Vector3f size = s.objects[k].size_lwh.cast<float>();
    const Eigen::Vector3f half(size.x() / 2 + pad, size.y() / 2 + pad, 0.5f), centre(0, 0, -size.z() / 2);
    Eigen::AlignedBox3f world;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3f corner = centre + Eigen::Vector3f(c & 1 ? half.x() : -half.x(), c & 2 ? half.y() : -half.y(), c & 4 ? half.z() : -half.z());
      world.extend(p->cast<float>() * corner);
    }
    any.extend(world);
    bands.push_back({p->inverse().cast<float>(), size, world});
  }
  if (bands.empty()) return out;
  for (size_t j = 0; j < placed.size(); ++j) {
    const float* g = placed.at(j);
    const Eigen::Vector3f w(g[kPosX], g[kPosY], g[kPosZ]);
    // Most Gaussians (facades, trees, the sky) are nowhere near a band: one box test skips them.
    if (!any.contains(w) || owner[size_t(source[j])] >= 0) continue;
    for (const auto& b : bands) {
      if (!b.world.contains(w)) continue;
      const Eigen::Vector3f q = b.to_box * w;
      if (std::abs(q.x()) < b.size.x() / 2 + pad && std::abs(q.y()) < b.size.y() / 2 + pad && std::abs(q.z() + b.size.z() / 2) < 0.5f) {
        out[j] = 1;
        break;
      }
    }
  }
  return out;
}

namespace {

// Background Gaussians that drifted into a parked object's box join the object (its frame).
int adopt_into_static_objects(Gaussians& g, std::vector<int>& owner, const scene::Scene& s,
                              const std::vector<std::optional<Eigen::Isometry3d>>& boxes) {
  int moved = 0;
  for (size_t i = 0; i < g.size(); ++i) {
    if (owner[i] >= 0) continue;
    float* p = g.at(i);
    const Eigen::Vector3d w(p[kPosX], p[kPosY], p[kPosZ]);
    for (size_t k = 0; k < boxes.size(); ++k) {
      if (!boxes[k]) continue;
      const Eigen::Vector3d local = *boxes[k] * w;
      if (!inside_box(local, s.objects[k].size_lwh, 0.05)) continue;
      const Eigen::Matrix3f Rinv = boxes[k]->linear().cast<float>();
      p[kPosX] = float(local.x()), p[kPosY] = float(local.y()), p[kPosZ] = float(local.z());
      const Eigen::Quaternionf q = Eigen::Quaternionf(Rinv) * Eigen::Quaternionf(p[kRotW], p[kRotX], p[kRotY], p[kRotZ]);
      p[kRotW] = q.w(), p[kRotX] = q.x(), p[kRotY] = q.y(), p[kRotZ] = q.z();
      for (int c = 0; c < 3; ++c) {
        const Eigen::Vector3f kk = Rinv * Eigen::Vector3f(p[kColor + 4 * c + 1], p[kColor + 4 * c + 2], p[kColor + 4 * c + 3]);
        p[kColor + 4 * c + 1] = kk.x(), p[kColor + 4 * c + 2] = kk.y(), p[kColor + 4 * c + 3] = kk.z();
      }
      owner[i] = int(k);
      ++moved;
      break;
    }
  }
  return moved;
}

}  // namespace

scene::Camera scaled_camera(const scene::Camera& c, int max_width) {
  if (max_width <= 0 || c.width <= max_width) return c;
  const double s = double(max_width) / c.width;
  scene::Camera o = c;
  o.width = max_width;
  o.height = int(std::lround(c.height * s));
  o.fx *= s, o.fy *= s;
  // Pixel centres at integers: the scaled image's pixel i covers [i - 0.5, i + 0.5] / s - 0.5.
  o.cx = (c.cx + 0.5) * s - 0.5;
  o.cy = (c.cy + 0.5) * s - 0.5;
  return o;
}

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
