#pragma once
// Measuring deletion in views the radiance field renders, as in the main job's moved view, on
// the demo scene's shifted ground-truth views (noise-free, at the true poses). Every vehicle is
// removed from the field's render of each view, as the deletion agent removes them, and the
// result is scored against the truth where the deletion changed the render and the truth shows
// no vehicle (the vehicles' outlines and shadows at that instant are left out: the truth still
// has them). Four fills are compared on the same pixels: none (the field's render), the
// deletion without clearing the removed cars' paths, clearing every path pixel, and the
// deletion as the agent does it (clearing where the render and the ground map differ).
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::render::gs {
class RadianceField;
}

namespace chatsim::render::inpaint {

// Throws std::invalid_argument naming the file when the scene has no shifted ground-truth views,
// scene::SceneError naming the file and field when one is malformed.
nlohmann::json evaluate_moved_view_deletion(const scene::Scene& scene, std::shared_ptr<const gs::RadianceField> model,
                                            const std::string& save_dir = "");

}  // namespace chatsim::render::inpaint
