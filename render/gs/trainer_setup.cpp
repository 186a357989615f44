#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <opencv2/imgproc.hpp>

#include "common/scene/camera_model.hpp"
#include "render/color.hpp"
#include "render/gs/moving_mask.hpp"
#include "render/gs/trainer_parts.hpp"
#include "render/image_io.hpp"
#include "render/parallel.hpp"

namespace chatsim::render::gs {
namespace detail {

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

}  // namespace detail

using namespace detail;

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

}  // namespace chatsim::render::gs
