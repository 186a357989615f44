#include "agents/core/agent_registry.hpp"

#include <stdexcept>

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
       "command planning arrives with the agents' decisions issue (#5)"},
      {"view", "chatsim-view", "view adjustment: new camera extrinsics per frame",
       "view changes arrive with the agents' decisions issue (#5)"},
      {"background", "chatsim-background",
       "background rendering: exposure-aware radiance field, novel views, depth",
       "the radiance field arrives with the background rendering issue (#6)"},
      {"deletion", "chatsim-deletion", "vehicle deletion: masks and inpainting",
       "selection arrives with issue #5, inpainting with issue #8"},
      {"asset", "chatsim-asset", "3D asset management: asset bank and recolouring",
       "asset choice arrives with issue #5, the asset bank with issue #7"},
      {"motion", "chatsim-motion", "vehicle motion: placement and trajectories on the lane map",
       "placement and planning arrive with the agents' decisions issue (#5)"},
      {"foreground", "chatsim-foreground",
       "foreground rendering: path-traced vehicles lit by the estimated sky, composited",
       "path tracing and lighting arrive with the foreground rendering issue (#7)"},
  };
  return kinds;
}

const AgentKindInfo* find_agent_kind(const std::string& kind) {
  for (const auto& k : agent_kinds()) {
    if (k.kind == kind) return &k;
  }
  return nullptr;
}

std::unique_ptr<Agent> make_agent(const std::string& kind) {
  const AgentKindInfo* info = find_agent_kind(kind);
  if (info == nullptr) throw std::invalid_argument("unknown agent kind '" + kind + "'");
  return std::make_unique<NotYetImplementedAgent>(*info);
}

}  // namespace chatsim::agents
