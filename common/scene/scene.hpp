#pragma once
// The scene directory contract (`chatsim-scene/1`, ../shared/SCENE_FORMAT.md) as plain data.
// Loading validates everything and names the file, field and fix on the first problem.
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/scene/lane_map.hpp"
#include "common/scene/objects.hpp"

namespace chatsim::scene {

// A problem in a scene directory: which file, which field, what is wrong.
class SceneError : public std::runtime_error {
 public:
  SceneError(std::filesystem::path file, std::string field, const std::string& problem);
  const std::filesystem::path& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::filesystem::path file_;
  std::string field_;
};

struct Camera {
  std::string name;
  int width = 0;
  int height = 0;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  std::string distortion_model = "none";
  Eigen::Isometry3d sensor_to_ego = Eigen::Isometry3d::Identity();  // OpenCV camera -> ego FLU
};

struct ImageRef {
  std::filesystem::path path;          // relative to the scene directory
  double timestamp_s = 0;
  std::optional<double> exposure_s;    // absent: unknown, to be estimated
  std::optional<Eigen::Isometry3d> camera_to_world;  // overrides rig x ego pose
};

struct Frame {
  int index = 0;
  double timestamp_s = 0;
  Eigen::Isometry3d ego_to_world = Eigen::Isometry3d::Identity();
  std::map<std::string, ImageRef> images;  // by camera name
  std::filesystem::path lidar;             // empty: none
};

struct Scene {
  std::filesystem::path dir;
  std::string name;
  std::string source;
  double frame_rate_hz = 10;
  std::string ego_origin;
  bool layout_only = false;
  std::string lanes_source;                // "" or e.g. "derived_from_ego_path"
  std::vector<Camera> cameras;
  std::vector<Frame> frames;
  std::vector<ObjectTrack> objects;
  LaneMap lanes;

  const Camera* camera(const std::string& name) const;
  const Frame* frame(int index) const;  // by its index, not its position; nullptr: none
  const ObjectTrack* object(const std::string& id) const;
  // Camera (OpenCV) to world for one image: its own pose if it has one, else the ego pose at
  // the image's timestamp x rig.
  Eigen::Isometry3d camera_to_world(const Frame& frame, const Camera& camera) const;
  // The ego pose at time t: interpolated between frames (slerp), extrapolated along the first
  // or last step outside them.
  Eigen::Isometry3d ego_to_world_at(double t) const;
  // World to the ego frame at frame 0 (the frame the command cases speak in).
  Eigen::Isometry3d world_to_ego0() const;
  double duration_s() const;
};

struct LoadOptions {
  bool check_files = true;   // images and LiDAR files must exist (not for layout-only scenes)
};

// Loads and validates <dir>/scene.json and, when present, objects.json and lanes.json.
Scene load_scene(const std::filesystem::path& dir, const LoadOptions& options = {});

// Writes scene.json, objects.json and lanes.json (importers and generators use this).
void save_scene(const Scene& scene, const std::filesystem::path& dir);

}  // namespace chatsim::scene
