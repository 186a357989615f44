#pragma once
// Agents get a scene directory with every call; loading it once per change keeps calls fast.
#include <filesystem>
#include <memory>

#include "common/scene/scene.hpp"

namespace chatsim::agents {

// The scene at dir, loaded again only when its scene.json, objects.json or lanes.json changed.
// Throws scene::SceneError for a bad scene.
std::shared_ptr<const scene::Scene> cached_scene(const std::filesystem::path& dir);

}  // namespace chatsim::agents
