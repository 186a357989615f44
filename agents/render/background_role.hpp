#pragma once
// The background agent's role functions: make sure the scene has a trained radiance field
// (trained once, cached), and render the background of a view: the captured image itself where
// the view is the captured one (nothing to render), else the radiance field; depth always when
// a model exists.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "agents/core/agent.hpp"
#include "render/gs/model.hpp"

namespace chatsim::agents::render {

// Progress of long work (training): fraction 0..1 and a message.
using RoleProgress = std::function<void(double, const std::string&)>;

class BackgroundRole {
 public:
  // action "ensure_model" (args: preset), "render" (args: a RenderJob).
  AgentOutcome handle(const AgentCall& call, const RoleProgress& progress = {});
  // The model file for a scene and preset in the cache (may not exist yet).
  static std::filesystem::path model_path(const scene::Scene& scene, const std::string& preset);

 private:
  AgentOutcome ensure_model(const AgentCall& call, const RoleProgress& progress);
  AgentOutcome render(const AgentCall& call);
};

// Loads a model once per path (shared by the roles in one process).
std::shared_ptr<const chatsim::render::gs::RadianceField> load_model_cached(const std::filesystem::path& file);

}  // namespace chatsim::agents::render
