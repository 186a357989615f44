#pragma once
// Where trained models, lighting estimates and rendered stages are kept between runs:
// $CHATSIM_CACHE, else $XDG_CACHE_HOME/chatsim, else ~/.cache/chatsim. A scene is known by a
// hash of its files (scene.json, objects.json), so an edited scene gets fresh entries.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::agents::render {

std::filesystem::path cache_root();
// "<name>-<16 hex>": the scene's name and a hash of its description files.
std::string scene_key(const scene::Scene& scene);
std::filesystem::path scene_cache_dir(const scene::Scene& scene);
// A short stable hash of any JSON value (stage keys).
std::string json_hash(const nlohmann::json& value);

// What the deletion and foreground stages' outputs depend on besides their input stage
// (`after`): what they remove or add, and the versions of the code that makes them, including
// the light estimator's (its sun casts deletion's shadow masks and lights the added vehicles),
// so a stage made with an older estimate is not reused.
nlohmann::json deletion_stage_key(const nlohmann::json& after, const nlohmann::json& removed);
nlohmann::json foreground_stage_key(const nlohmann::json& after, const nlohmann::json& added, int spp);

// A stage's folder is complete when its done.json exists (written last).
bool stage_complete(const std::filesystem::path& dir);
void mark_stage_complete(const std::filesystem::path& dir, const nlohmann::json& info);

}  // namespace chatsim::agents::render
