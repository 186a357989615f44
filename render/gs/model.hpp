#pragma once
// A trained radiance field of one scene: background Gaussians in the world, Gaussians of each
// labelled object in the object's own frame (so moving cars stay sharp and one object can be
// left out), the far-field sky texture, and what training learned about the capture: an
// exposure correction per image and a pose correction per camera and per image.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"
#include "render/gs/gaussians.hpp"
#include "render/gs/rasterizer.hpp"
#include "render/gs/sky_texture.hpp"

namespace chatsim::render::gs {

// A pose correction: a rotation vector and a translation (camera frame), right-multiplied.
struct PoseCorrection {
  Eigen::Vector3f rotation = Eigen::Vector3f::Zero();
  Eigen::Vector3f translation = Eigen::Vector3f::Zero();
  Eigen::Isometry3d transform() const;
};

struct ImageKey {
  int frame = 0;
  std::string camera;
  bool operator<(const ImageKey& o) const { return frame != o.frame ? frame < o.frame : camera < o.camera; }
};

class RadianceField {
 public:
  Gaussians gaussians;
  std::vector<int> owner;                       // -1: background; else index into objects
  std::vector<std::string> objects;             // object ids (objects.json)
  SkyTexture sky{128, 64};
  std::map<ImageKey, float> log_exposure;       // learned correction per image (log scale)
  std::map<std::string, PoseCorrection> camera_correction;
  std::map<ImageKey, PoseCorrection> image_correction;
  bool use_exposure = true;                     // exposure_s used in training (false: ablation)
  nlohmann::json info = nlohmann::json::object();  // scene, preset, training statistics

  // The Gaussians placed in the world at `time_s` (objects moved along their tracks; objects
  // without a box at that time, or in `hide`, are left out). With an object hidden, so is what
  // the background learned inside the space the object's box swept over its track: a moving
  // car its own Gaussians did not fully explain leaves ghosts of itself (and its shadow's
  // darkening, just above the road) smeared along its path.
  Gaussians placed(const scene::Scene& scene, double time_s, const std::vector<std::string>& hide = {},
                   std::vector<int>* source = nullptr) const;
  // The same into `out`, whose memory is reused (training places them every iteration).
  void place(const scene::Scene& scene, double time_s, const std::vector<std::string>& hide, Gaussians& out,
             std::vector<int>* source = nullptr) const;

  // Renders a view: HDR radiance (scene units), expected depth (m; +inf where transparent) and alpha.
  GsImage render(const scene::Scene& scene, const scene::Camera& camera, const Eigen::Isometry3d& camera_to_world,
                 double time_s, const std::vector<std::string>& hide = {}, int threads = 0) const;
  // The same view rendered only inside `roi` (the camera cropped to it), placed in full-size
  // images: radiance and alpha zero outside it, depth 0 there.
  GsImage render_region(const scene::Scene& scene, const scene::Camera& camera, const Eigen::Isometry3d& camera_to_world,
                        double time_s, const std::vector<std::string>& hide, const cv::Rect& roi) const;
  // The recorded pose of an image with the learned corrections applied.
  Eigen::Isometry3d corrected_pose(const scene::Scene& scene, int frame, const std::string& camera) const;
  // The exposure (s) to show an image of the scene with: exposure_s x the learned correction.
  double exposure(const scene::Scene& scene, int frame, const std::string& camera) const;

  void save(const std::filesystem::path& file) const;
  static RadianceField load(const std::filesystem::path& file);  // throws naming the file
};

// An object's pose (box centre, yaw) at a time, interpolated along its track.
std::optional<Eigen::Isometry3d> object_pose(const scene::Scene& scene, const scene::ObjectTrack& object, double time_s);
// The GsView of a camera at a pose (OpenCV camera frame).
GsView make_view(const scene::Camera& camera, const Eigen::Isometry3d& camera_to_world);

}  // namespace chatsim::render::gs
