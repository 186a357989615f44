#pragma once
// Converts one scene of the standard nuScenes tables to our scene format: per-image ego poses
// (cameras fire at different times; each frame levelled by its static boxes, as nuScenes' ego
// poses have no height), calibration, key-frame LiDAR in each frame's ego frame,
// boxes as tracks by instance, an estimated colour per vehicle, and a lane map derived from the
// ego path (nuScenes data here has no map), marked as derived.
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/import/level_frames.hpp"
#include "common/scene/scene.hpp"

namespace chatsim::import {

struct NuScenesOptions {
  std::filesystem::path dataroot;            // holds <version>/*.json and samples/
  std::string version = "v1.0-mini";
  std::string scene = "scene-0916";
  std::vector<std::string> cameras = {"CAM_FRONT", "CAM_FRONT_LEFT", "CAM_FRONT_RIGHT"};
  bool lidar = true;
  bool estimate_colors = true;
  bool level_frames = true;                  // fit each frame's height and tilt to the static boxes (level_frames.hpp)
  bool force_output = false;                 // replace a chatsim output of another kind at `out` (--force)
};

class ImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Progress: (done, total, what).
using Progress = std::function<void(int, int, const std::string&)>;

// Writes the scene to out (new, empty or a scene chatsim wrote: common/util/output_dir.hpp;
// through a temporary folder swapped in when complete) and returns it; OutputDirError for any
// other folder, before anything is read;
// `levels`, when given, receives the frames' height and tilt corrections (empty: none applied).
scene::Scene import_nuscenes(const NuScenesOptions& options, const std::filesystem::path& out,
                             const Progress& progress = {}, std::map<int, FrameLevel>* levels = nullptr);

}  // namespace chatsim::import
