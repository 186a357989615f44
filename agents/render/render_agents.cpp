#include "agents/render/render_agents.hpp"

#include <algorithm>
#include <cstdlib>

#include "agents/core/agent_registry.hpp"
#include "agents/decision/decision_agents.hpp"
#include "agents/render/background_role.hpp"
#include "agents/render/deletion_role.hpp"
#include "agents/render/foreground_role.hpp"

namespace chatsim::agents::render {
namespace {

class BackgroundAgent : public Agent {
 public:
  explicit BackgroundAgent(PipelineProgress progress) : progress_(std::move(progress)) {}
  const std::string& kind() const override {
    static const std::string k = "background";
    return k;
  }
  AgentOutcome handle(const AgentCall& call) override {
    return role_.handle(call, [this](double f, const std::string& m) {
      if (progress_) progress_("training", f, m);
    });
  }

 private:
  BackgroundRole role_;
  PipelineProgress progress_;
};

// The deletion agent decides which objects a phrase means, and removes them from images.
class DeletionAgent : public Agent {
 public:
  DeletionAgent() : decide_(make_agent("deletion")) {}
  const std::string& kind() const override { return decide_->kind(); }
  AgentOutcome handle(const AgentCall& call) override {
    if (call.action == "inpaint") return deletion_inpaint(call);
    return decide_->handle(call);
  }

 private:
  std::unique_ptr<Agent> decide_;
};

class ForegroundAgent : public Agent {
 public:
  const std::string& kind() const override {
    static const std::string k = "foreground";
    return k;
  }
  AgentOutcome handle(const AgentCall& call) override {
    if (call.action == "render") return foreground_render(call);
    if (call.action == "light") return foreground_light(call);
    return AgentOutcome::failure(ErrorKind::BadRequest, "foreground has no action '" + call.action + "' (actions: render, light)");
  }
};

}  // namespace

std::unique_ptr<Agent> make_render_agent(const std::string& kind, const PipelineProgress& progress) {
  if (kind == "background") return std::make_unique<BackgroundAgent>(progress);
  if (kind == "deletion") return std::make_unique<DeletionAgent>();
  if (kind == "foreground") return std::make_unique<ForegroundAgent>();
  return nullptr;
}

std::unique_ptr<Agent> make_rendering_manager(manager::AgentCaller caller, const PipelineProgress& progress,
                                              manager::FanoutCaller fanout) {
  std::shared_ptr<llm::Backend> backend = llm::make_backend();
  manager::Renderer renderer = [caller, progress, fanout](const std::string& scene, const nlohmann::json& edit,
                                                          const std::string& out, const std::string& preset, bool force) {
    RenderTask task;
    task.scene_dir = scene;
    task.edit_state = edit;
    task.output_dir = out;
    task.force_output = force;
    const RenderPreset p = render_preset(preset);  // the manager checked the name
    task.preset = p.model;
    task.foreground_spp = p.foreground_spp;
    // A fixed number of samples per pixel for the added vehicles, whatever the preset.
    if (const char* spp = std::getenv("CHATSIM_FOREGROUND_SPP"); spp != nullptr && std::atoi(spp) > 0)
      task.foreground_spp = std::min(4096, std::atoi(spp));
    return render_edit(caller, task, progress, fanout);
  };
  return manager::make_manager_agent(std::move(caller), backend, std::move(renderer));
}

}  // namespace chatsim::agents::render
