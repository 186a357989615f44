#include "agents/render/render_job.hpp"

#include <fstream>
#include <stdexcept>

#include "render/gs/model.hpp"

namespace chatsim::agents::render {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
[[noreturn]] void bad(const std::string& field, const std::string& why) { throw std::invalid_argument("args." + field + ": " + why); }
}  // namespace

RenderJob RenderJob::from_json(const json& a) {
  if (!a.is_object()) bad("(root)", "must be a JSON object");
  RenderJob j;
  try {
    if (a.contains("frames")) j.frames = a["frames"].get<std::vector<int>>();
    if (a.contains("cameras")) j.cameras = a["cameras"].get<std::vector<std::string>>();
    if (a.contains("view")) j.view = view::view_state_from_json(a["view"]);
    if (a.contains("in")) j.in = a["in"].get<std::string>();
    if (a.contains("out")) j.out = a["out"].get<std::string>();
    if (a.contains("model")) j.model = a["model"].get<std::string>();
    if (a.contains("removed")) j.removed = a["removed"].get<std::vector<std::string>>();
    if (a.contains("added")) j.added = a["added"];
    if (a.contains("spp")) j.spp = a["spp"].get<int>();
  } catch (const json::exception& e) {
    bad("(fields)", std::string("wrong type: ") + e.what());
  }
  if (j.out.empty()) bad("out", "missing: the folder this stage writes");
  if (!j.added.is_array()) bad("added", "must be the edit state's list of added vehicles");
  if (j.spp < 0 || j.spp > 4096) bad("spp", "must be 0 (the default) or 1..4096 samples per pixel");
  return j;
}

json RenderJob::to_json() const {
  json j{{"frames", frames}, {"cameras", cameras}, {"view", view::to_json(view)}, {"out", out.string()},
         {"removed", removed}, {"added", added}};
  if (!in.empty()) j["in"] = in.string();
  if (!model.empty()) j["model"] = model.string();
  if (spp > 0) j["spp"] = spp;
  return j;
}

bool is_original_view(const view::ViewState& v) {
  return v.translation_m[0] == 0 && v.translation_m[1] == 0 && v.translation_m[2] == 0 && v.yaw_deg == 0 && v.pitch_deg == 0 &&
         v.ego_motion == "none";
}

std::vector<ViewImage> view_images(const scene::Scene& s, const RenderJob& job, const chatsim::render::gs::RadianceField* model) {
  const bool original = is_original_view(job.view);
  const auto moved = original ? std::vector<std::vector<Eigen::Isometry3d>>{} : view::camera_poses(s, job.view);
  std::vector<ViewImage> out;
  for (size_t fi = 0; fi < s.frames.size(); ++fi) {
    const auto& f = s.frames[fi];
    if (!job.frames.empty() && std::find(job.frames.begin(), job.frames.end(), f.index) == job.frames.end()) continue;
    for (size_t ci = 0; ci < s.cameras.size(); ++ci) {
      const auto& cam = s.cameras[ci];
      if (!job.cameras.empty() && std::find(job.cameras.begin(), job.cameras.end(), cam.name) == job.cameras.end()) continue;
      ViewImage im;
      im.frame = f.index;
      im.camera = cam.name;
      im.cam = cam;
      const auto it = f.images.find(cam.name);
      im.time = it != f.images.end() ? it->second.timestamp_s : f.timestamp_s;
      im.original = original && it != f.images.end();
      const Eigen::Isometry3d recorded = s.camera_to_world(f, cam);
      const Eigen::Isometry3d base = (model != nullptr && it != f.images.end()) ? model->corrected_pose(s, f.index, cam.name) : recorded;
      if (original) {
        im.pose = base;
      } else {
        // The view's change of the rig pose (in the world), applied to this image's pose.
        const Eigen::Isometry3d rig = f.ego_to_world * cam.sensor_to_ego;
        im.pose = moved[fi][ci] * rig.inverse() * base;
      }
      out.push_back(im);
    }
  }
  return out;
}

fs::path radiance_file(const fs::path& stage, const std::string& camera, int frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d.exr", frame);
  return stage / camera / buf;
}

fs::path depth_file(const fs::path& stage, const std::string& camera, int frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d_depth.exr", frame);
  return stage / camera / buf;
}

fs::path exposure_file(const fs::path& stage, const std::string& camera, int frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%06d.json", frame);
  return stage / camera / buf;
}

void write_exposure(const fs::path& stage, const std::string& camera, int frame, double exposure) {
  const fs::path f = exposure_file(stage, camera, frame);
  fs::create_directories(f.parent_path());
  const fs::path tmp = f.string() + ".part";
  std::ofstream(tmp) << json{{"exposure_s", exposure}}.dump() << "\n";
  fs::rename(tmp, f);
}

double read_exposure(const fs::path& stage, const std::string& camera, int frame) {
  const fs::path f = exposure_file(stage, camera, frame);
  if (!fs::exists(f)) return 1.0;
  return json::parse(std::ifstream(f)).value("exposure_s", 1.0);
}

}  // namespace chatsim::agents::render
