#include "render/gs/model.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include <unistd.h>

namespace chatsim::render::gs {
namespace fs = std::filesystem;
using nlohmann::json;

Eigen::Isometry3d PoseCorrection::transform() const {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  const double angle = rotation.norm();
  if (angle > 1e-12) t.linear() = Eigen::AngleAxisd(angle, rotation.cast<double>() / angle).toRotationMatrix();
  t.translation() = translation.cast<double>();
  return t;
}

std::optional<Eigen::Isometry3d> object_pose(const scene::Scene& scene, const scene::ObjectTrack& o, double t) {
  // The frames around t, by timestamp.
  const auto& fr = scene.frames;
  if (fr.empty()) return std::nullopt;
  size_t k = 0;
  while (k + 1 < fr.size() && fr[k + 1].timestamp_s <= t) ++k;
  const size_t k1 = std::min(k + 1, fr.size() - 1);
  const double span = fr[k1].timestamp_s - fr[k].timestamp_s;
  const double a = span > 0 ? std::clamp((t - fr[k].timestamp_s) / span, 0.0, 1.0) : 0.0;
  auto p0 = o.at(fr[k].index), p1 = o.at(fr[k1].index);
  if (!p0 && !p1) return std::nullopt;
  if (!p0) p0 = p1;
  if (!p1) p1 = p0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = p0->center * (1 - a) + p1->center * a;
  const double yaw = p0->yaw + a * std::remainder(p1->yaw - p0->yaw, 2 * M_PI);
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

GsView make_view(const scene::Camera& c, const Eigen::Isometry3d& c2w) {
  GsView v;
  v.width = c.width, v.height = c.height;
  v.fx = float(c.fx), v.fy = float(c.fy), v.cx = float(c.cx), v.cy = float(c.cy);
  v.rotation = c2w.linear().cast<float>();
  v.center = c2w.translation().cast<float>();
  return v;
}

namespace {

// The space an object's box swept along its track, padded, from just above the ground (the
// road's own Gaussians under a parked car stay).
class SweptBoxes {
 public:
  void add(const scene::ObjectTrack& o) {
    constexpr float kPad = 0.25f, kAboveGround = 0.15f;
    for (const auto& tp : o.track) {
      Box b;
      b.center = tp.center.cast<float>();
      b.cos_yaw = float(std::cos(tp.yaw)), b.sin_yaw = float(std::sin(tp.yaw));
      b.half = Eigen::Vector3f(float(o.size_lwh.x()) / 2 + kPad, float(o.size_lwh.y()) / 2 + kPad, float(o.size_lwh.z()) / 2 + kPad);
      b.zmin = b.center.z() - float(o.size_lwh.z()) / 2 + kAboveGround;
      const float r = std::hypot(b.half.x(), b.half.y());
      lo_ = lo_.cwiseMin(Eigen::Vector3f(b.center.x() - r, b.center.y() - r, b.zmin));
      hi_ = hi_.cwiseMax(b.center + Eigen::Vector3f(r, r, b.half.z()));
      boxes_.push_back(b);
    }
  }
  bool contains(const Eigen::Vector3f& p) const {
    if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any()) return false;
    for (const auto& b : boxes_) {
      const Eigen::Vector3f d = p - b.center;
      const float along = b.cos_yaw * d.x() + b.sin_yaw * d.y(), across = -b.sin_yaw * d.x() + b.cos_yaw * d.y();
      if (std::abs(along) <= b.half.x() && std::abs(across) <= b.half.y() && std::abs(d.z()) <= b.half.z() && p.z() >= b.zmin) return true;
    }
    return false;
  }

 private:
  struct Box {
    Eigen::Vector3f center, half;
    float cos_yaw = 1, sin_yaw = 0, zmin = 0;
  };
  std::vector<Box> boxes_;
  Eigen::Vector3f lo_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f hi_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
};

}  // namespace

Gaussians RadianceField::placed(const scene::Scene& scene, double t, const std::vector<std::string>& hide,
                                std::vector<int>* source) const {
  Gaussians out;
  place(scene, t, hide, out, source);
  return out;
}

void RadianceField::place(const scene::Scene& scene, double t, const std::vector<std::string>& hide, Gaussians& out,
                          std::vector<int>* source) const {
  std::vector<SweptBoxes> swept;
  for (const auto& id : hide)
    if (const auto* o = scene.object(id); o != nullptr && !o->track.empty()) swept.emplace_back().add(*o);
  std::vector<std::optional<Eigen::Isometry3f>> pose(objects.size());
  for (size_t k = 0; k < objects.size(); ++k) {
    if (std::find(hide.begin(), hide.end(), objects[k]) != hide.end()) continue;
    if (const auto* o = scene.object(objects[k]))
      if (const auto p = object_pose(scene, *o, t)) pose[k] = p->cast<float>();
  }
  out.p.clear();
  out.p.reserve(gaussians.p.size());
  if (source) source->clear();
  for (size_t i = 0; i < gaussians.size(); ++i) {
    const int own = owner[i];
    if (own >= 0 && !pose[size_t(own)]) continue;
    if (own < 0 && !swept.empty()) {
      const Eigen::Vector3f p(gaussians.at(i)[kPosX], gaussians.at(i)[kPosY], gaussians.at(i)[kPosZ]);
      if (std::any_of(swept.begin(), swept.end(), [&](const SweptBoxes& b) { return b.contains(p); })) continue;
    }
    const size_t j = out.size();
    out.resize(j + 1);
    float* d = out.at(j);
    const float* s = gaussians.at(i);
    std::copy(s, s + kParamCount, d);
    if (source) source->push_back(int(i));
    if (own < 0) continue;
    const Eigen::Isometry3f& T = *pose[size_t(own)];
    const Eigen::Vector3f p = T * Eigen::Vector3f(s[kPosX], s[kPosY], s[kPosZ]);
    d[kPosX] = p.x(), d[kPosY] = p.y(), d[kPosZ] = p.z();
    const Eigen::Quaternionf q = Eigen::Quaternionf(T.linear()) * Eigen::Quaternionf(s[kRotW], s[kRotX], s[kRotY], s[kRotZ]);
    d[kRotW] = q.w(), d[kRotX] = q.x(), d[kRotY] = q.y(), d[kRotZ] = q.z();
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3f k = T.linear() * Eigen::Vector3f(s[kColor + 4 * c + 1], s[kColor + 4 * c + 2], s[kColor + 4 * c + 3]);
      d[kColor + 4 * c + 1] = k.x(), d[kColor + 4 * c + 2] = k.y(), d[kColor + 4 * c + 3] = k.z();
    }
  }
}

GsImage RadianceField::render(const scene::Scene& scene, const scene::Camera& camera, const Eigen::Isometry3d& c2w,
                              double t, const std::vector<std::string>& hide, int threads) const {
  const Gaussians g = placed(scene, t, hide);
  Rasterizer r;
  r.threads = threads;
  GsImage img = r.forward(g, &sky, make_view(camera, c2w));
  // Expected depth where something is there.
  for (int y = 0; y < img.depth.rows; ++y)
    for (int x = 0; x < img.depth.cols; ++x) {
      const float a = img.alpha.at<float>(y, x);
      img.depth.at<float>(y, x) = a > 0.5f ? img.depth.at<float>(y, x) / a : std::numeric_limits<float>::infinity();
    }
  return img;
}

GsImage RadianceField::render_region(const scene::Scene& scene, const scene::Camera& camera, const Eigen::Isometry3d& c2w,
                                     double t, const std::vector<std::string>& hide, const cv::Rect& roi) const {
  GsImage full{cv::Mat(camera.height, camera.width, CV_32FC3, cv::Scalar::all(0)), cv::Mat(camera.height, camera.width, CV_32F, cv::Scalar(0)),
               cv::Mat(camera.height, camera.width, CV_32F, cv::Scalar(0))};
  const cv::Rect r = roi & cv::Rect(0, 0, camera.width, camera.height);
  if (r.empty()) return full;
  scene::Camera crop = camera;
  crop.width = r.width, crop.height = r.height;
  crop.cx -= r.x, crop.cy -= r.y;
  const GsImage out = render(scene, crop, c2w, t, hide);
  out.radiance.copyTo(full.radiance(r));
  out.depth.copyTo(full.depth(r));
  out.alpha.copyTo(full.alpha(r));
  return full;
}

Eigen::Isometry3d RadianceField::corrected_pose(const scene::Scene& scene, int frame, const std::string& camera) const {
  const auto* cam = scene.camera(camera);
  const scene::Frame* fr = scene.frame(frame);
  if (cam == nullptr || fr == nullptr) throw std::invalid_argument("no image of camera '" + camera + "' at frame " + std::to_string(frame));
  Eigen::Isometry3d pose = scene.camera_to_world(*fr, *cam);
  if (auto it = camera_correction.find(camera); it != camera_correction.end()) pose = pose * it->second.transform();
  if (auto it = image_correction.find({frame, camera}); it != image_correction.end()) pose = pose * it->second.transform();
  return pose;
}

double RadianceField::exposure(const scene::Scene& scene, int frame, const std::string& camera) const {
  double e = 1.0;
  if (const auto* f = scene.frame(frame))
    if (auto it = f->images.find(camera); it != f->images.end() && it->second.exposure_s && use_exposure) e = *it->second.exposure_s;
  if (auto it = log_exposure.find({frame, camera}); it != log_exposure.end()) return e * std::exp(double(it->second));
  // An image not trained on (held out): the mean correction of its camera.
  double sum = 0;
  int n = 0;
  for (const auto& [k, v] : log_exposure)
    if (k.camera == camera) sum += v, ++n;
  return e * std::exp(n > 0 ? sum / n : 0.0);
}

namespace {
constexpr char kMagic[8] = {'C', 'S', 'G', 'S', '0', '0', '0', '1'};

json pose_json(const PoseCorrection& p) {
  return {{"rotation", {p.rotation.x(), p.rotation.y(), p.rotation.z()}},
          {"translation", {p.translation.x(), p.translation.y(), p.translation.z()}}};
}
PoseCorrection pose_from(const json& j) {
  PoseCorrection p;
  for (int k = 0; k < 3; ++k) p.rotation[k] = j["rotation"][size_t(k)], p.translation[k] = j["translation"][size_t(k)];
  return p;
}
}  // namespace

void RadianceField::save(const fs::path& file) const {
  json h = info;
  h["count"] = gaussians.size();
  h["params"] = int(kParamCount);
  h["objects"] = objects;
  h["sky"] = {sky.width(), sky.height()};
  h["use_exposure"] = use_exposure;
  json exp = json::array(), cams = json::object(), imgs = json::array();
  for (const auto& [k, v] : log_exposure) exp.push_back({{"frame", k.frame}, {"camera", k.camera}, {"log", v}});
  for (const auto& [c, p] : camera_correction) cams[c] = pose_json(p);
  for (const auto& [k, p] : image_correction) {
    json j = pose_json(p);
    j["frame"] = k.frame, j["camera"] = k.camera;
    imgs.push_back(j);
  }
  h["log_exposure"] = exp;
  h["camera_correction"] = cams;
  h["image_correction"] = imgs;
  const std::string header = h.dump();
  if (!file.parent_path().empty()) fs::create_directories(file.parent_path());
  const fs::path tmp = file.string() + ".part" + std::to_string(getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    const uint64_t len = header.size();
    out.write(kMagic, 8);
    out.write(reinterpret_cast<const char*>(&len), 8);
    out.write(header.data(), std::streamsize(len));
    out.write(reinterpret_cast<const char*>(gaussians.p.data()), std::streamsize(gaussians.p.size() * sizeof(float)));
    out.write(reinterpret_cast<const char*>(owner.data()), std::streamsize(owner.size() * sizeof(int)));
    out.write(reinterpret_cast<const char*>(sky.data().data()), std::streamsize(sky.data().size() * sizeof(float)));
    if (!out) throw std::runtime_error("cannot write " + file.string());
  }
  fs::rename(tmp, file);
}

RadianceField RadianceField::load(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  char magic[8];
  uint64_t len = 0;
  in.read(magic, 8);
  in.read(reinterpret_cast<char*>(&len), 8);
  if (!in || std::string(magic, 8) != std::string(kMagic, 8))
    throw std::runtime_error(file.string() + ": not a chatsim radiance field (train one with chatsim train)");
  if (len > (1u << 30)) throw std::runtime_error(file.string() + ": corrupt header");
  std::string header(len, '\0');
  in.read(header.data(), std::streamsize(len));
  RadianceField m;
  try {
    const json h = json::parse(header);
    if (h.at("params").get<int>() != kParamCount) throw std::runtime_error("made by another version (parameter count)");
    const size_t n = h.at("count");
    m.objects = h.at("objects").get<std::vector<std::string>>();
    m.sky = SkyTexture(h.at("sky")[0], h.at("sky")[1]);
    m.use_exposure = h.value("use_exposure", true);
    for (const auto& e : h.at("log_exposure")) m.log_exposure[{e["frame"], e["camera"]}] = e["log"];
    for (const auto& [c, p] : h.at("camera_correction").items()) m.camera_correction[c] = pose_from(p);
    for (const auto& p : h.at("image_correction")) m.image_correction[{p["frame"], p["camera"]}] = pose_from(p);
    m.info = h;
    for (const char* k : {"count", "params", "objects", "sky", "log_exposure", "camera_correction", "image_correction"}) m.info.erase(k);
    m.gaussians.resize(n);
    m.owner.resize(n);
    in.read(reinterpret_cast<char*>(m.gaussians.p.data()), std::streamsize(m.gaussians.p.size() * sizeof(float)));
    in.read(reinterpret_cast<char*>(m.owner.data()), std::streamsize(n * sizeof(int)));
    in.read(reinterpret_cast<char*>(m.sky.data().data()), std::streamsize(m.sky.data().size() * sizeof(float)));
    if (!in) throw std::runtime_error("truncated");
    for (int o : m.owner)
      if (o < -1 || o >= int(m.objects.size())) throw std::runtime_error("an owner index is out of range");
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": corrupt radiance field: " + e.what());
  }
  return m;
}

}  // namespace chatsim::render::gs
