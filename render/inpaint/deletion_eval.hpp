#pragma once
// Measuring deletion on the demo scene: each vehicle with clean plates is removed in turn, by
// this method and by the cv::inpaint (Telea) baseline on the same masks, and compared with the
// plates inside the mask (PSNR, SSIM), for temporal flicker (how much the filled ground
// changes from frame to frame, in 8-bit levels), and for time per image.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"
#include "render/inpaint/deletion.hpp"

namespace chatsim::render::inpaint {

struct DeletionEvalOptions {
  std::vector<std::string> objects;  // empty: every vehicle with plates
  int max_objects = 0;               // 0: no limit (the largest plates first)
  std::string save_dir;              // before / after / baseline / plate images
  BackgroundRenderer background;     // what the ground map cannot fill (the agent's radiance field); empty: 2D inpainting
  bool baseline = true;              // also run the Telea baseline (false: its fields are left out of the report)
  std::function<void(const std::string&)> progress;  // one line per object, when set
};

nlohmann::json evaluate_deletion(const scene::Scene& scene, const DeletionEvalOptions& options);

// For a scene without clean plates (a real capture): removes one parked vehicle (the one that
// covers the most of an image while staying whole in it, with no labelled object in front)
// and writes `<prefix>before.png`, `<prefix>after.png` and `<prefix>telea.png` for a person
// to look at. With the scene's radiance field, also `<prefix>after-field.png`: the field
// renders what the ground map cannot fill, as the deletion agent does. Returns what it did.
nlohmann::json deletion_before_after(const scene::Scene& scene, const std::string& prefix,
                                     std::shared_ptr<const gs::RadianceField> field = nullptr);

}  // namespace chatsim::render::inpaint
