// The manager as an Agent: the action a bus request names ("chat", "reset") turned into a
// round of the conversation and, when asked, a rendered result; the folder it renders into is
// checked before the round changes anything.
#include "agents/manager/manager.hpp"

#include <memory>

#include "common/scene/scene.hpp"
#include "common/util/output_dir.hpp"
#include "common/util/preset_names.hpp"

namespace chatsim::agents::manager {

using nlohmann::json;

namespace {

class ManagerAgent : public Agent {
 public:
  ManagerAgent(AgentCaller caller, std::shared_ptr<llm::Backend> backend, Renderer renderer)
      : manager_(std::move(caller), std::move(backend)), renderer_(std::move(renderer)) {}
  const std::string& kind() const override {
    static const std::string k = "manager";
    return k;
  }
  AgentOutcome handle(const AgentCall& call) override {
    const std::string id = call.args.value("conversation_id", std::string("default"));
    if (call.action == "reset") {
      manager_.reset(id);
      return AgentOutcome::success({{"message", "conversation reset"}});
    }
    if (call.action != "chat")
      return AgentOutcome::failure(ErrorKind::BadRequest, "manager has no action '" + call.action + "' (actions: chat, reset)");
    if (call.scene.empty())
      return AgentOutcome::failure(ErrorKind::BadRequest, "no scene given: pass the scene directory (--scene DIR)");
    // Checked before the round changes the conversation, so a typo loses nothing.
    const std::string preset = call.args.value("preset", std::string());
    if (!preset.empty() && !is_preset_name(preset))
      return AgentOutcome::failure(ErrorKind::BadRequest,
                                   "unknown rendering preset '" + preset + "' (use " + std::string(kPresetChoices) + ")");
    const bool render = call.args.value("render", false);
    const std::string out = call.args.value("output_dir", std::string());
    const bool force = call.args.value("force_output", false);
    if (render) {
      if (out.empty()) return AgentOutcome::failure(ErrorKind::BadRequest, "rendering needs an output folder (output_dir)");
      if (!renderer_)
        return AgentOutcome::failure(ErrorKind::NotImplemented, "this manager was started without the rendering pipeline");
      // Also before the round changes the conversation: a folder it may not write costs nothing.
      try {
        check_render_output(out, call.scene, force);
      } catch (const OutputDirError& e) {
        return AgentOutcome::failure(ErrorKind::BadRequest, e.what());
      }
    }
    try {
      const auto r = manager_.chat(id, call.scene, call.args.value("command", std::string()));
      json result{{"message", r.message}, {"edit_state", r.edit_state}};
      if (render) {
        const AgentOutcome rendered = renderer_(call.scene, r.edit_state, out, preset, force);
        if (!rendered.ok) {
          AgentOutcome failed = rendered;
          failed.message = "the decisions were made (" + r.message + ") but rendering failed: " + rendered.message;
          return failed;
        }
        result["output_dir"] = rendered.result.value("output_dir", out);
        result["render"] = rendered.result;
        result["message"] = r.message + " Rendered to " + result["output_dir"].get<std::string>() + ".";
      }
      return AgentOutcome::success(result);
    } catch (const scene::SceneError& e) {
      return AgentOutcome::failure(ErrorKind::BadRequest, std::string("bad scene: ") + e.what());
    } catch (const llm::BackendError& e) {
      return AgentOutcome::failure(ErrorKind::Unavailable, std::string("manager's language model failed: ") + e.what());
    } catch (const std::exception& e) {
      return AgentOutcome::failure(ErrorKind::Unavailable, e.what());
    }
  }

 private:
  Manager manager_;
  Renderer renderer_;
};

}  // namespace

void check_render_output(const std::string& out, const std::string& scene, bool force) {
  refuse_output_over_input(out, scene, "--out", "--scene");
  check_output_dir(out, "result", force);
}

std::unique_ptr<Agent> make_manager_agent(AgentCaller caller, std::shared_ptr<llm::Backend> backend, Renderer renderer) {
  return std::make_unique<ManagerAgent>(std::move(caller), std::move(backend), std::move(renderer));
}

}  // namespace chatsim::agents::manager
