#pragma once
// One rendering request as the rendering agents receive it (the JSON arguments of their
// "render"/"inpaint" actions), and the images it covers: which frames and cameras, where each
// camera is in the requested view, and where each stage keeps its files.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "agents/view/view.hpp"
#include "common/scene/scene.hpp"

namespace chatsim::render::gs {
class RadianceField;
}

namespace chatsim::agents::render {

struct RenderJob {
  std::vector<int> frames;            // empty: every frame
  std::vector<std::string> cameras;   // empty: every camera
  view::ViewState view;
  std::filesystem::path in;           // the previous stage's folder (deletion, foreground)
  std::filesystem::path out;          // this stage's folder
  std::filesystem::path model;        // radiance field (may be empty)
  std::vector<std::string> removed;   // deletion
  nlohmann::json added = nlohmann::json::array();  // foreground: the edit state's added vehicles
  int spp = 0;                        // foreground: path-tracing samples per pixel (0: the agent's default)

  // Throws std::invalid_argument naming the field and the fix.
  static RenderJob from_json(const nlohmann::json& args);
  nlohmann::json to_json() const;
};

bool is_original_view(const view::ViewState& v);

// One image of a job: a frame and camera, the camera's pose in the requested view, the time it
// shows (the captured image's timestamp, where objects are) and whether it is the captured view.
struct ViewImage {
  int frame = 0;
  std::string camera;
  scene::Camera cam;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double time = 0;
  bool original = false;
};

// Poses start from the recorded ones, with the radiance field's corrections when there is one.
std::vector<ViewImage> view_images(const scene::Scene& scene, const RenderJob& job, const chatsim::render::gs::RadianceField* model);

std::filesystem::path radiance_file(const std::filesystem::path& stage, const std::string& camera, int frame);
std::filesystem::path depth_file(const std::filesystem::path& stage, const std::string& camera, int frame);
// Each image's exposure (s) to show it with, beside it: {"exposure_s": e}. One small file per
// image, so workers rendering different images of one stage never write the same file.
std::filesystem::path exposure_file(const std::filesystem::path& stage, const std::string& camera, int frame);
void write_exposure(const std::filesystem::path& stage, const std::string& camera, int frame, double exposure);
double read_exposure(const std::filesystem::path& stage, const std::string& camera, int frame);  // 1 when missing

}  // namespace chatsim::agents::render
