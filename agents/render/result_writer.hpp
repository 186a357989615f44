#pragma once
// What a rendered result holds besides its frames: the labels of every vehicle in every frame
// after the edit (removed ones gone, added ones on their trajectories) as JSON and in the KITTI
// label format per camera and frame, and the side-by-side video of all cameras.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "agents/render/render_job.hpp"
#include "common/scene/scene.hpp"

namespace chatsim::agents::render {

// {"frames": [{"frame", "timestamp_s", "objects": [{id, category, source, center, size_lwh, yaw,
// "cameras": {name: {bbox_xyxy, truncated}}}]}]}
nlohmann::json edited_labels(const scene::Scene& scene, const nlohmann::json& edit_state, const std::vector<ViewImage>& images);
// One KITTI label file per camera and frame under dir/<camera>/<frame>.txt.
void write_kitti_labels(const nlohmann::json& labels, const std::vector<ViewImage>& images, const std::filesystem::path& dir);
// KITTI's type names for our categories.
std::string kitti_type(const std::string& category);

// frames[frame] = one image per camera, left to right; writes H.264 where OpenCV can, else
// MPEG-4 Part 2. Returns the codec used.
std::string write_side_by_side_video(const std::filesystem::path& file, const std::vector<std::vector<cv::Mat>>& frames, double fps);

}  // namespace chatsim::agents::render
