#include "render/gs/pose_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "common/scene/scene_json.hpp"

namespace chatsim::render::gs {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Errors {
  std::vector<double> initial_deg, initial_m, refined_deg, refined_m;
  std::array<std::vector<double>, 3> initial_axes, refined_axes;  // signed, about the camera's x, y, z
  void add(const Eigen::Isometry3d& truth, const Eigen::Isometry3d& initial, const Eigen::Isometry3d& refined) {
    auto rotation_deg = [&](const Eigen::Isometry3d& p) {
      return Eigen::AngleAxisd(truth.linear().transpose() * p.linear()).angle() * 180.0 / M_PI;
    };
    auto axes = [&](const Eigen::Isometry3d& p, std::array<std::vector<double>, 3>& out) {
      const Eigen::AngleAxisd aa(truth.linear().transpose() * p.linear());
      const Eigen::Vector3d v = aa.axis() * aa.angle() * 180.0 / M_PI;
      for (int k = 0; k < 3; ++k) out[size_t(k)].push_back(v[k]);
    };
    axes(initial, initial_axes), axes(refined, refined_axes);
    initial_deg.push_back(rotation_deg(initial)), refined_deg.push_back(rotation_deg(refined));
    initial_m.push_back((initial.translation() - truth.translation()).norm());
    refined_m.push_back((refined.translation() - truth.translation()).norm());
  }
};

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

json summary(const Errors& e) {
  auto axes = [](const std::array<std::vector<double>, 3>& a) { return json::array({median(a[0]), median(a[1]), median(a[2])}); };
  return {{"count", e.refined_m.size()},
          {"initial", {{"rotation_deg", median(e.initial_deg)}, {"rotation_xyz_deg", axes(e.initial_axes)}, {"translation_m", median(e.initial_m)}}},
          {"refined", {{"rotation_deg", median(e.refined_deg)}, {"rotation_xyz_deg", axes(e.refined_axes)}, {"translation_m", median(e.refined_m)}}}};
}

}  // namespace

std::optional<json> evaluate_pose_error(const RadianceField& model, const scene::Scene& s) {
  const fs::path file = s.dir / "ground_truth" / "poses.json";
  if (!fs::exists(file) || model.image_correction.empty()) return std::nullopt;
  const json doc = scene::read_json_file(file);
  const scene::FieldReader images = scene::FieldReader(file, doc).at("images");
  std::map<std::string, Errors> per_camera;
  Errors all;
  for (size_t i = 0; i < images.array_size(); ++i) {
    const scene::FieldReader p = images.at(i);
    const int frame = p.at("frame").integer();
    const std::string camera = p.at("camera").str();
    if (!model.image_correction.count({frame, camera})) continue;  // held out: never refined
    const Eigen::Isometry3d truth = p.at("camera_to_world_true").rigid();
    const scene::Frame* f = s.frame(frame);
    const scene::Camera* cam = s.camera(camera);
    if (f == nullptr || cam == nullptr) continue;
    const Eigen::Isometry3d initial = s.camera_to_world(*f, *cam);  // where training started
    const Eigen::Isometry3d refined = model.corrected_pose(s, frame, camera);
    per_camera[camera].add(truth, initial, refined);
    all.add(truth, initial, refined);
  }
  if (all.refined_m.empty()) return std::nullopt;
  json cameras = json::object();
  for (const auto& [name, e] : per_camera) cameras[name] = summary(e);
  return json{{"cameras", cameras}, {"all", summary(all)},
              {"what", "median pose error against ground_truth/poses.json over the training images: the scene's pose (where training starts), and after pose refinement"}};
}

}  // namespace chatsim::render::gs
