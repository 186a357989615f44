#include "agents/core/agent_registry.hpp"

#include <map>
#include <mutex>
#include <stdexcept>

#include "agents/decision/decision_agents.hpp"

namespace chatsim::agents {
namespace {

class NotYetImplementedAgent final : public Agent {
 public:
  explicit NotYetImplementedAgent(const AgentKindInfo& info) : info_(info) {}
  const std::string& kind() const override { return info_.kind; }
  AgentOutcome handle(const AgentCall& call) override {
    return AgentOutcome::failure(
        ErrorKind::NotImplemented,
        "the " + info_.kind + " agent cannot do '" + call.action + "' yet: " + info_.pending);
  }

 private:
  AgentKindInfo info_;
};

}  // namespace

const std::vector<AgentKindInfo>& agent_kinds() {
  static const std::vector<AgentKindInfo> kinds = {
      {"manager", "chatsim-manager",
       "project manager: splits commands into instructions, routes them, keeps the edit state",
       ""},
      {"view", "chatsim-view", "view adjustment: new camera extrinsics per frame",
       ""},
      {"background", "chatsim-background",
       "background rendering: exposure-aware radiance field, novel views, depth",
       "rendering agents are made by agents/render (make_render_agent), not by this decision-only registry"},
      {"deletion", "chatsim-deletion", "vehicle deletion: masks and inpainting", ""},
      {"asset", "chatsim-asset", "3D asset management: asset bank and recolouring", ""},
      {"motion", "chatsim-motion", "vehicle motion: placement and trajectories on the lane map",
       ""},
      {"foreground", "chatsim-foreground",
       "foreground rendering: path-traced vehicles lit by the estimated sky, composited",
       "rendering agents are made by agents/render (make_render_agent), not by this decision-only registry"},
  };
  return kinds;
}

const AgentKindInfo* find_agent_kind(const std::string& kind) {
  for (const auto& k : agent_kinds()) {
    if (k.kind == kind) return &k;
  }
  return nullptr;
}

manager::AgentCaller local_caller(std::shared_ptr<llm::Backend> backend) {
  struct Local {
    std::mutex mu;
    std::map<std::string, std::unique_ptr<Agent>> agents;
  };
  auto local = std::make_shared<Local>();
  local->agents["view"] = make_view_agent(backend);
  local->agents["deletion"] = make_deletion_agent(backend);
  local->agents["asset"] = make_asset_agent(backend);
  local->agents["motion"] = make_motion_agent(backend);
  return [local](const std::string& kind, const AgentCall& call) {
    std::lock_guard lock(local->mu);
    const auto it = local->agents.find(kind);
    if (it == local->agents.end())
      return AgentOutcome::failure(ErrorKind::Unavailable, "no in-process agent of kind '" + kind + "'");
    return it->second->handle(call);
  };
}

std::unique_ptr<Agent> make_agent(const std::string& kind, manager::AgentCaller caller) {
  const AgentKindInfo* info = find_agent_kind(kind);
  if (info == nullptr) throw std::invalid_argument("unknown agent kind '" + kind + "'");
  std::shared_ptr<llm::Backend> backend = llm::make_backend();
  if (kind == "manager") return manager::make_manager_agent(caller ? caller : local_caller(backend), backend);
  if (kind == "view") return make_view_agent(backend);
  if (kind == "deletion") return make_deletion_agent(backend);
  if (kind == "asset") return make_asset_agent(backend);
  if (kind == "motion") return make_motion_agent(backend);
  return std::make_unique<NotYetImplementedAgent>(*info);
}

}  // namespace chatsim::agents
