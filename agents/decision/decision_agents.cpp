#include "agents/decision/decision_agents.hpp"

#include <algorithm>

#include "agents/asset/asset_choice.hpp"
#include "agents/core/scene_cache.hpp"
#include "agents/deletion/deletion.hpp"
#include "agents/motion/planner.hpp"
#include "agents/view/view.hpp"
#include "common/scene/scene_json.hpp"

namespace chatsim::agents {
namespace {

using nlohmann::json;

// Shared shape: check the action, run, turn exceptions into clear failures.
class DecisionAgent : public Agent {
 public:
  DecisionAgent(std::string kind, std::shared_ptr<llm::Backend> backend) : kind_(std::move(kind)), backend_(std::move(backend)) {}
  const std::string& kind() const override { return kind_; }

  AgentOutcome handle(const AgentCall& call) override {
    try {
      return run(call);
    } catch (const scene::SceneError& e) {
      return AgentOutcome::failure(ErrorKind::BadRequest, std::string("bad scene: ") + e.what());
    } catch (const llm::BackendError& e) {
      return AgentOutcome::failure(ErrorKind::Unavailable, kind_ + " agent's language model failed: " + e.what());
    } catch (const json::exception& e) {
      return AgentOutcome::failure(ErrorKind::BadRequest, kind_ + " agent: malformed arguments: " + e.what());
    }
  }

 protected:
  virtual AgentOutcome run(const AgentCall& call) = 0;

  json decide(const std::string& instruction) { return backend_->complete(llm::prompt_for(kind_), instruction); }

  AgentOutcome unknown_action(const AgentCall& call, const char* known) const {
    return AgentOutcome::failure(ErrorKind::BadRequest,
                                 kind_ + " agent has no action '" + call.action + "' (actions: " + known + ")");
  }

  std::string kind_;
  std::shared_ptr<llm::Backend> backend_;
};

class ViewAgent : public DecisionAgent {
 public:
  using DecisionAgent::DecisionAgent;
  AgentOutcome run(const AgentCall& call) override {
    if (call.action == "adjust") {
      const json said = decide(call.args.at("instruction").get<std::string>());
      auto change = view::view_change_from_json(said);
      const auto current = view::view_state_from_json(call.args.value("view", json::object()));
      if (change.needs_map())
        change = view::resolve_on_map(change, *cached_scene(call.scene), current.translation_m[1]);
      if (change.to_lane)
        return AgentOutcome::failure(ErrorKind::BadRequest, "the map has no " + *change.to_lane +
                                                                " lane beside the ego to move the view to");
      if (change.to_junction)
        return AgentOutcome::failure(ErrorKind::BadRequest, "the map has no junction ahead of the ego on its lane "
                                                            "to move the view to; say how far, e.g. '30 m ahead'");
      const auto state = view::apply(current, change);
      return AgentOutcome::success({{"change", view::to_json(change)}, {"view", view::to_json(state)}});
    }
    if (call.action == "poses") {
      const auto scene = cached_scene(call.scene);
      const auto poses = view::camera_poses(*scene, view::view_state_from_json(call.args.value("view", json::object())));
      json frames = json::array();
      for (const auto& f : poses) {
        json cams = json::object();
        for (size_t c = 0; c < f.size(); ++c) cams[scene->cameras[c].name] = scene::matrix_json(f[c]);
        frames.push_back(cams);
      }
      return AgentOutcome::success({{"camera_to_world", frames}});
    }
    return unknown_action(call, "adjust, poses");
  }
};

// A labelled object's box at its first frame and its mean speed over the clip (world frame).
json start_box(const scene::Scene& scene, const scene::ObjectTrack& o) {
  const auto& first = o.track.front();
  const auto& last = o.track.back();
  const auto time_of = [&](int frame) {
    return frame >= 0 && size_t(frame) < scene.frames.size() ? scene.frames[size_t(frame)].timestamp_s : 0.0;
  };
  const double dt = time_of(last.frame) - time_of(first.frame);
  const double speed = dt > 0 ? (last.center - first.center).head<2>().norm() / dt : 0.0;
  json box{{"id", o.id}, {"x", first.center.x()}, {"y", first.center.y()}, {"yaw", first.yaw},
           {"size_lwh", {o.size_lwh.x(), o.size_lwh.y(), o.size_lwh.z()}}, {"speed_mps", speed}, {"wrong_way", false}};
  if (o.color_rgb) box["color_rgb"] = *o.color_rgb;  // "the same colour as the coach"
  return box;
}

class DeletionAgent : public DecisionAgent {
 public:
  using DecisionAgent::DecisionAgent;
  AgentOutcome run(const AgentCall& call) override {
    const auto scene = cached_scene(call.scene);
    if (call.action == "locate") {  // where the given objects start (removed ones too)
      json objects = json::array();
      for (const auto& id : call.args.value("ids", std::vector<std::string>{}))
        for (const auto& o : scene->objects)
          if (o.id == id && !o.track.empty()) objects.push_back(start_box(*scene, o));
      return AgentOutcome::success({{"objects", objects}});
    }
    if (call.action != "select") return unknown_action(call, "select, locate");
    const json request = decide(call.args.at("instruction").get<std::string>());
    auto removed = call.args.value("removed", std::vector<std::string>{});
    // "among": select only among these ("put the truck back": among the removed ones).
    if (call.args.contains("among")) {
      const auto among = call.args["among"].get<std::vector<std::string>>();
      removed.clear();
      for (const auto& o : scene->objects)
        if (std::find(among.begin(), among.end(), o.id) == among.end()) removed.push_back(o.id);
    }
    const auto it = call.args.value("it", std::vector<std::string>{});
    const auto sel = deletion::select_objects(*scene, deletion::deletion_request_from_json(request), removed, it);
    // Where each selected object starts, so that a vehicle can be placed relative to it.
    json objects = json::array();
    for (const auto& id : sel.ids)
      for (const auto& o : scene->objects)
        if (o.id == id && !o.track.empty()) objects.push_back(start_box(*scene, o));
    return AgentOutcome::success({{"request", request}, {"ids", sel.ids}, {"problems", sel.problems}, {"objects", objects}});
  }
};

class AssetAgent : public DecisionAgent {
 public:
  using DecisionAgent::DecisionAgent;
  AgentOutcome run(const AgentCall& call) override {
    if (call.action != "choose") return unknown_action(call, "choose");
    json request = call.args.contains("request") ? call.args["request"] : decide(call.args.at("instruction").get<std::string>());
    std::optional<asset::AssetChoice> base;
    if (call.args.contains("base")) base = asset::asset_choice_from_json(call.args["base"]);
    const auto choice = asset::choose_asset(asset::asset_request_from_json(request), base);
    return AgentOutcome::success({{"request", request}, {"choice", asset::to_json(choice)}});
  }
};

class MotionAgent : public DecisionAgent {
 public:
  using DecisionAgent::DecisionAgent;
  AgentOutcome run(const AgentCall& call) override {
    if (call.action == "decide") return AgentOutcome::success({{"intent", decide(call.args.at("instruction").get<std::string>())}});
    if (call.action != "plan") return unknown_action(call, "decide, plan");
    const auto scene = cached_scene(call.scene);
    const auto& a = call.args;
    motion::MotionIntent intent = motion::intent_from_json(a.value("base_intent", json::object()));
    json said = json::object();
    if (a.contains("intent")) said = a["intent"];
    else if (a.contains("instruction")) said = decide(a["instruction"].get<std::string>());
    intent.merge(motion::intent_from_json(said));
    motion::PlanRequest req;
    req.intent = intent;
    const auto size = a.value("size_lwh", std::array<double, 3>{4.5, 1.9, 1.5});
    req.size_lwh = {size[0], size[1], size[2]};
    req.type = a.value("type", "car");
    req.strict = a.value("strict", false);
    // "the ego drives slowly" then "a truck ahead at the same speed": the speed the view gives it.
    if (const auto ego = a.value("ego_motion", std::string("none")); ego != "none") req.ego_speed_mps = view::ego_speed_mps(ego);
    req.obstacles = motion::scene_obstacles(*scene, a.value("removed", std::vector<std::string>{}));
    if (a.value("ego_motion", std::string("none")) == "none") req.ego = motion::ego_obstacle(*scene);
    for (const auto& o : a.value("others", json::array())) {
      std::vector<motion::Pose2> traj;
      for (const auto& p : o.at("trajectory")) traj.push_back({p.at("x"), p.at("y"), p.at("yaw")});
      const auto s = o.at("size_lwh").get<std::array<double, 3>>();
      req.obstacles.push_back(motion::trajectory_obstacle(o.at("id"), {s[0], s[1], s[2]}, traj));
    }
    if (a.contains("anchor")) {
      const auto& an = a["anchor"];
      const auto s = an.at("size_lwh").get<std::array<double, 3>>();
      req.anchor = motion::Anchor{{an.at("x"), an.at("y"), an.at("yaw")}, {s[0], s[1], s[2]},
                                  an.value("speed_mps", 0.0), an.value("wrong_way", false)};
    } else if (intent.relative) {
      return AgentOutcome::failure(ErrorKind::BadRequest, "placement relative to '" + intent.relative->to +
                                                              "' needs that vehicle's start (args.anchor)");
    }
    const auto plan = motion::plan_motion(*scene, req);
    if (!plan.ok) return AgentOutcome::failure(ErrorKind::BadRequest, plan.reason);
    json traj = json::array();
    for (size_t i = 0; i < plan.trajectory.size(); ++i)
      traj.push_back({{"t_s", std::round(plan.t_s[i] * 1000) / 1000}, {"x", std::round(plan.trajectory[i].x * 1000) / 1000},
                      {"y", std::round(plan.trajectory[i].y * 1000) / 1000},
                      {"yaw", std::round(plan.trajectory[i].yaw * 10000) / 10000}});
    return AgentOutcome::success({{"said", said}, {"intent", motion::to_json(intent)},
                                  {"resolved", motion::to_json(plan.resolved)}, {"trajectory", traj},
                                  {"lane", plan.lane}, {"speed_mps", plan.speed_mps}, {"notes", plan.notes},
                                  {"not_done", plan.not_done}});
  }
};

}  // namespace

std::unique_ptr<Agent> make_view_agent(std::shared_ptr<llm::Backend> b) { return std::make_unique<ViewAgent>("view", b); }
std::unique_ptr<Agent> make_deletion_agent(std::shared_ptr<llm::Backend> b) {
  return std::make_unique<DeletionAgent>("deletion", b);
}
std::unique_ptr<Agent> make_asset_agent(std::shared_ptr<llm::Backend> b) { return std::make_unique<AssetAgent>("asset", b); }
std::unique_ptr<Agent> make_motion_agent(std::shared_ptr<llm::Backend> b) { return std::make_unique<MotionAgent>("motion", b); }

}  // namespace chatsim::agents
