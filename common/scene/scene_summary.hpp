#pragma once
// What `chatsim scene info` prints: cameras, frames, extent, objects by category, lanes.
#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::scene {

nlohmann::json summarize(const Scene& scene);
std::string summary_text(const nlohmann::json& summary);

}  // namespace chatsim::scene
