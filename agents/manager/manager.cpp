#include "agents/manager/manager.hpp"

#include <algorithm>
#include <sstream>

#include "agents/core/scene_cache.hpp"
#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"

namespace chatsim::agents::manager {
namespace {

using nlohmann::json;

// Values the motion agent found out of range refuse the instruction, each with its reason.
bool refused_for_range(Conversation& c, const std::string& text, const json& intent) {
  if (!intent.contains("problems")) return false;
  for (const auto& p : intent["problems"]) c.unresolved.push_back({{"instruction", text}, {"reason", p}});
  return true;
}

}  // namespace

Manager::Manager(AgentCaller caller, std::shared_ptr<llm::Backend> backend)
    : caller_(std::move(caller)), backend_(std::move(backend)) {}

void Manager::reset(const std::string& id) {
  std::lock_guard lock(mu_);
  conversations_.erase(id);
  last_used_.erase(id);
}

AgentOutcome Manager::call(const std::string& kind, const Conversation& c, const std::string& action, json args) {
  return caller_(kind, AgentCall{action, c.scene_dir, std::move(args)});
}

ChatResult Manager::chat(const std::string& id, const std::string& scene_dir, const std::string& command) {
  std::lock_guard lock(mu_);
  cached_scene(scene_dir);  // a bad scene fails here, with file and field
  if (!conversations_.count(id) && conversations_.size() >= kMaxConversations) {
    const auto oldest = std::min_element(last_used_.begin(), last_used_.end(),
                                         [](const auto& a, const auto& b) { return a.second < b.second; });
    conversations_.erase(oldest->first);
    last_used_.erase(oldest);
  }
  last_used_[id] = ++uses_;
  Conversation& c = conversations_[id];
  if (!c.scene_dir.empty() && c.scene_dir != scene_dir) c = Conversation{};
  // A round that fails half-way (an agent gone) must not leave half its edits behind.
  const Conversation before = c;
  try {
    return run_round(c, scene_dir, command);
  } catch (...) {
    c = before;
    throw;
  }
}

ChatResult Manager::run_round(Conversation& c, const std::string& scene_dir, const std::string& command) {
  c.scene_dir = scene_dir;
  const size_t unresolved_before = c.unresolved.size();
  Round round;
  const std::string trimmed = command.substr(0, 2000);
  std::vector<Instruction> instructions;
  if (text::words(trimmed).empty()) {
    instructions.push_back({"unclear", command, "", 1});
  } else {
    instructions = instructions_from_json(backend_->complete(llm::prompt_for("manager"), trimmed));
    continue_previous_round(c, trimmed, instructions);
  }
  if (command.size() > 2000)
    c.unresolved.push_back({{"instruction", command.substr(0, 80) + "..."},
                            {"reason", "the command is " + std::to_string(command.size()) +
                                           " characters long; only the first 2000 were read"}});
  // The paper's order: view first, then deletions, then vehicles in the order said.
  std::stable_sort(instructions.begin(), instructions.end(), [](const Instruction& a, const Instruction& b) {
    auto phase = [](const std::string& k) {
      return k == "undo" ? -1 : k == "view" ? 0 : (k == "delete" || k == "restore") ? 1 : 2;
    };
    return phase(a.kind) < phase(b.kind);
  });
  if (replaces_last_round(c, trimmed, instructions)) {
    back_to_round_start(c);
    round.done.push_back("Replaced round " + std::to_string(c.rounds.size()) + ".");
  }
  remember_for_undo(c);
  for (const auto& in : instructions) {
    round.instructions.push_back(in.kind + ": " + in.text);
    run_instruction(c, in, round);
  }
  if (!round.added_now.empty()) c.last_group = round.added_now;
  for (size_t i = unresolved_before; i < c.unresolved.size(); ++i) c.unresolved[i]["round"] = c.rounds.size() + 1;
  c.rounds.push_back({{"command", command}, {"instructions", round.instructions}});
  ChatResult out;
  out.edit_state = edit_state(c);
  std::ostringstream msg;
  for (size_t i = 0; i < round.done.size(); ++i) msg << (i ? " " : "") << round.done[i];
  out.message = msg.str();
  if (out.message.empty()) out.message = "Nothing was changed.";
  return out;
}

void Manager::run_instruction(Conversation& c, const Instruction& in, Round& round) {
  const size_t before = c.unresolved.size();
  if (in.kind == "view") do_view(c, in, round);
  else if (in.kind == "delete") do_delete(c, in, round);
  else if (in.kind == "restore") do_restore(c, in, round);
  else if (in.kind == "undo") do_undo(c, in, round);
  else if (in.kind == "add") do_add(c, in, round);
  else if (in.kind == "revise") do_revise(c, in, round);
  else if (in.kind == "remove_added") do_remove_added(c, in, round);
  else if (in.kind == "traffic_jam" || in.kind == "busy_road" || in.kind == "construction_zone" ||
           in.kind == "road_block")
    do_abstract(c, in, round);
  else if (!in.target.empty())  // decompose named what cannot be added
    c.unresolved.push_back({{"instruction", in.text},
                            {"reason", "a " + in.target + " is not something that can be added to a road scene "
                                       "(vehicles, cones and barriers can)"}});
  else
    c.unresolved.push_back({{"instruction", in.text},
                            {"reason", "not understood as an edit (add, delete, put back or revise a vehicle, or move "
                                       "the view); try e.g. 'add a red car 20 m ahead'"}});
  for (size_t i = before; i < c.unresolved.size(); ++i)
    round.done.push_back("Not done: '" + c.unresolved[i]["instruction"].get<std::string>() + "': " +
                         c.unresolved[i]["reason"].get<std::string>() + ".");
}

void Manager::do_view(Conversation& c, const Instruction& in, Round& round) {
  const auto out = call("view", c, "adjust", {{"instruction", in.text}, {"view", c.view}});
  if (!out.ok && out.error != ErrorKind::BadRequest) throw std::runtime_error("view agent: " + out.message);
  if (!out.ok) {  // a lane the map does not have: this instruction is not done, the conversation goes on
    c.unresolved.push_back({{"instruction", in.text}, {"reason", out.message}});
    return;
  }
  if (out.result["change"].empty()) {
    c.unresolved.push_back({{"instruction", in.text}, {"reason", "no distance, angle or ego motion found to apply to the view"}});
    return;
  }
  c.view = out.result["view"];
  round.done.push_back("View: " + out.result["change"].dump() + ".");
}

void Manager::do_delete(Conversation& c, const Instruction& in, Round& round) {
  // A brand (recorded objects carry none), an order word, or the colour of one vehicle added in
  // this conversation: the user speaks of what was added ("remove the Porsche", "delete the
  // first van", "delete the red car" just after adding one).
  if (!c.added.empty()) {
    const auto w = text::words(in.text);
    const std::string ref = reference_in(in.text);
    const bool one_by_colour = !lexicon::find_colors(w).empty() &&
                               !text::has_any(w, {"all", "every", "each", "parked", "recorded", "original", "other"});
    const bool named = !lexicon::find_brands(w).empty() || text::has_any(w, {"first", "second", "third", "last"}) ||
                       one_by_colour;
    if (named && ref != "it" && !resolve(c, ref).empty()) {
      do_remove_added(c, {"remove_added", in.text, ref, 1}, round);
      return;
    }
  }
  // "remove the truck", then "and the car behind it": "it" is what was removed last.
  json args{{"instruction", in.text}, {"removed", c.removed}};
  if (!c.removal_batches.empty()) args["it"] = c.removal_batches.back();
  const auto out = call("deletion", c, "select", args);
  if (!out.ok) throw std::runtime_error("deletion agent: " + out.message);
  const auto ids = out.result["ids"].get<std::vector<std::string>>();
  if (ids.empty()) {
    // Maybe it names a vehicle added earlier ("remove the police car").
    const auto added = resolve(c, reference_in(in.text));
    const auto w = text::words(in.text);
    if (!added.empty() && !lexicon::find_types(w).empty() && reference_in(in.text) != "it") {
      do_remove_added(c, {"remove_added", in.text, reference_in(in.text), 1}, round);
      return;
    }
  }
  for (const auto& p : out.result["problems"]) c.unresolved.push_back({{"instruction", in.text}, {"reason", p}});
  if (ids.empty()) return;
  c.removed.insert(c.removed.end(), ids.begin(), ids.end());
  c.removal_batches.push_back(ids);
  std::string list;
  for (const auto& id : ids) list += (list.empty() ? "" : ", ") + id;
  round.done.push_back("Removed " + std::to_string(ids.size()) + " object(s): " + list + ".");
}

void Manager::do_restore(Conversation& c, const Instruction& in, Round& round) {
  if (c.removal_batches.empty()) {
    c.unresolved.push_back({{"instruction", in.text}, {"reason", "nothing has been deleted in this conversation"}});
    return;
  }
  const auto w = text::words(in.text);
  if (restore_described(c, w, round)) return;
  const bool all = text::has_any(w, {"all", "every", "everything", "them"});
  // "put both back": removals from the last, until two objects are back.
  const bool both = text::has_any(w, {"both"});
  std::vector<std::string> back;
  while (!c.removal_batches.empty()) {
    back.insert(back.end(), c.removal_batches.back().begin(), c.removal_batches.back().end());
    c.removal_batches.pop_back();
    if (!all && (!both || back.size() >= 2)) break;
  }
  for (const auto& id : back) c.removed.erase(std::remove(c.removed.begin(), c.removed.end(), id), c.removed.end());
  round.done.push_back("Put back " + std::to_string(back.size()) + " object(s).");
}

// "bring back the black one", "put the bus back": of the removed objects, those the words
// describe. False when the words describe none (the last removal comes back instead).
bool Manager::restore_described(Conversation& c, const std::vector<std::string>& w, Round& round) {
  std::vector<std::string> description;
  for (const auto& x : w)
    if (!text::has_any({x}, {"bring", "put", "back", "restore", "please", "again", "undelete", "keep", "spare",
                             "though", "but", "actually"}))
      description.push_back(x);
  const bool describes = !lexicon::find_types(description).empty() || !lexicon::find_colors(description).empty();
  if (!describes) return false;
  // Selected among the removed objects ("the truck" is the removed one, not the nearest truck).
  const auto out = call("deletion", c, "select", {{"instruction", "remove " + text::join(description)},
                                                  {"among", c.removed}});
  std::vector<std::string> back;
  for (const auto& o : out.ok ? out.result.value("objects", json::array()) : json::array()) {
    const auto id = o.value("id", std::string());
    if (std::find(c.removed.begin(), c.removed.end(), id) != c.removed.end()) back.push_back(id);
  }
  if (back.empty()) return false;
  for (const auto& id : back) {
    c.removed.erase(std::remove(c.removed.begin(), c.removed.end(), id), c.removed.end());
    for (auto& batch : c.removal_batches) batch.erase(std::remove(batch.begin(), batch.end(), id), batch.end());
  }
  std::erase_if(c.removal_batches, [](const std::vector<std::string>& b) { return b.empty(); });
  round.done.push_back("Put back " + std::to_string(back.size()) + " object(s).");
  return true;
}

json Manager::others_json(const Conversation& c, int except) const {
  json others = json::array();
  for (size_t i = 0; i < c.added.size(); ++i) {
    if (int(i) == except) continue;
    others.push_back({{"id", c.added[i].id}, {"size_lwh", c.added[i].asset["size_lwh"]}, {"trajectory", c.added[i].trajectory}});
  }
  return others;
}

bool Manager::plan_motion(Conversation& c, AddedVehicle& v, const json& args_in, const std::string& text) {
  json args = args_in;
  if (c.view.is_object()) args["ego_motion"] = c.view.value("ego_motion", "none");  // "at the same speed as me"
  speed_of_vehicle(c, args["intent"], v.id);
  const auto plan = call("motion", c, "plan", args);
  if (!plan.ok) {
    // A plan that cannot be made is an answer; an agent that failed is not.
    if (plan.error != ErrorKind::BadRequest) throw std::runtime_error("motion agent: " + plan.message);
    c.unresolved.push_back({{"instruction", text}, {"reason", v.id + ": " + plan.message}});
    return false;
  }
  v.intent = plan.result["intent"];
  // Later rounds must find the same anchor, whatever "it" means by then.
  if (args.contains("anchor") && v.intent.contains("relative")) v.intent["relative"]["to"] = args["anchor"]["id"];
  v.resolved = plan.result["resolved"];
  v.trajectory = plan.result["trajectory"];
  v.speed_mps = plan.result["speed_mps"];
  v.lane = plan.result["lane"];
  for (const auto& n : plan.result["notes"]) c.notes.push_back(v.id + ": " + n.get<std::string>());
  for (const auto& n : plan.result.value("not_done", json::array()))
    c.unresolved.push_back({{"instruction", text}, {"reason", v.id + ": " + n.get<std::string>()}});
  return true;
}

bool Manager::add_one(Conversation& c, const json& asset_args, const json& motion_said, const std::string& text,
                      Round& round, bool strict, const json* group_anchor) {
  const auto asset = call("asset", c, "choose", asset_args);
  if (!asset.ok) throw std::runtime_error("asset agent: " + asset.message);
  const json choice = asset.result["choice"];
  json args{{"intent", motion_said}, {"size_lwh", choice["size_lwh"]}, {"type", choice["type"]},
            {"removed", c.removed}, {"others", others_json(c, -1)}, {"strict", strict}};
  if (motion_said.contains("relative")) {
    const auto anchor = group_anchor != nullptr ? std::optional<json>(*group_anchor)
                                                : find_anchor(c, motion_said["relative"].value("to", "it"), -1);
    if (!anchor) {
      const std::string to = motion_said["relative"].value("to", "");
      c.unresolved.push_back({{"instruction", text},
                              {"reason", to == "removed" ? "'there' or 'in its place' names no place: nothing has been "
                                                           "removed in this conversation"
                                                         : "no vehicle, added or recorded, matches '" + to +
                                                               "' to place it relative to"}});
      return false;
    }
    args["anchor"] = *anchor;
  }
  AddedVehicle v;
  v.id = "added_" + std::to_string(c.next_id);
  v.asset = choice;
  if (!plan_motion(c, v, args, text)) return false;
  ++c.next_id;
  if (choice.contains("note")) c.notes.push_back(v.id + ": " + choice["note"].get<std::string>());
  c.added.push_back(v);
  c.last_ref = int(c.added.size()) - 1;
  round.added_now.push_back(c.last_ref);
  round.done.push_back("Added " + v.id + " (" + choice["asset"].get<std::string>() + ", " +
                       v.resolved.value("action", "straight") + (v.lane.empty() ? "" : ", lane " + v.lane) + ").");
  return true;
}

void Manager::do_add(Conversation& c, const Instruction& in, Round& round) {
  json asset_args{{"instruction", in.text}};
  if (!in.target.empty()) {  // "another one": a copy of the referenced vehicle
    const auto ref = resolve(c, in.target);
    if (!ref.empty()) asset_args["base"] = c.added[size_t(ref.front())].asset;
  }
  // Ask the asset agent once for the count before planning any.
  const auto probe = call("asset", c, "choose", asset_args);
  if (!probe.ok) throw std::runtime_error("asset agent: " + probe.message);
  const int count = probe.result["request"].value("count", 1);
  if (count > kMaxAddedPerInstruction) {
    c.unresolved.push_back({{"instruction", in.text},
                            {"reason", "asked for " + std::to_string(count) + " vehicles; at most " +
                                           std::to_string(kMaxAddedPerInstruction) +
                                           " fit on the lanes of one scene at once, so none were added"}});
    return;
  }
  const auto decided = call("motion", c, "decide", {{"instruction", in.text}});
  if (!decided.ok) throw std::runtime_error("motion agent: " + decided.message);
  if (refused_for_range(c, in.text, decided.result["intent"])) return;
  json args = asset_args;
  args["request"] = probe.result["request"];
  // "two motorbikes next to the black one": each by the one named, not the second by the first.
  const json& intent = decided.result["intent"];
  const auto anchor = count > 1 && intent.contains("relative")
                          ? find_anchor(c, intent["relative"].value("to", "it"), -1) : std::nullopt;
  for (int k = 0; k < count; ++k)
    if (!add_one(c, args, intent, in.text, round, false, anchor ? &*anchor : nullptr)) break;
}

void Manager::do_revise(Conversation& c, const Instruction& in, Round& round) {
  // "turn it 5 degrees left" with nothing added: "it" is the view.
  if (c.added.empty() && in.target == "it" &&
      !text::quantities(text::words(in.text), {"meters", "meter", "m", "degrees", "degree", "cm"}).empty()) {
    do_view(c, in, round);
    return;
  }
  if (replace_recorded(c, in, round)) return;
  const auto targets = resolve(c, in.target);
  if (targets.empty()) {
    c.unresolved.push_back({{"instruction", in.text},
                            {"reason", c.added.empty() ? "no vehicle has been added yet, and recorded vehicles can only be "
                                                         "deleted, not changed"
                                                       : "no added vehicle matches '" + in.target + "'"}});
    return;
  }
  const std::string rest = colours_of_references(c, detail::strip_reference(detail::anchor_as_other(in.text), in.target));
  const auto decided = call("motion", c, "decide", {{"instruction", rest}});
  if (!decided.ok) throw std::runtime_error("motion agent: " + decided.message);
  if (refused_for_range(c, in.text, decided.result["intent"])) return;
  const json said_all = decided.result["intent"];
  bool changed_any = false;
  for (int t : targets) {
    AddedVehicle& v = c.added[size_t(t)];
    json said = said_all;
    // "no wait, in front of it": the vehicle that placed it ("the other vehicle" said, it has one).
    if (said.contains("relative") && said["relative"].value("to", "") == detail::kOtherVehicle &&
        v.intent.contains("relative") && v.intent["relative"].value("to", "") != "removed")
      said["relative"]["to"] = v.intent["relative"]["to"];
    const auto asset = call("asset", c, "choose", {{"instruction", rest}, {"base", v.asset}});
    if (!asset.ok) throw std::runtime_error("asset agent: " + asset.message);
    json req = asset.result["request"];
    req.erase("count");
    const bool asset_changed = !req.empty();
    if (!asset_changed && said.empty()) continue;
    changed_any = true;
    const bool resized = asset_changed && asset.result["choice"]["size_lwh"] != v.asset["size_lwh"];
    const json before = v.asset;
    if (asset_changed) v.asset = asset.result["choice"];
    if (said.empty() && !resized) {  // a new colour or brand of the same size: the motion stands
      round.done.push_back("Revised " + v.id + ".");
      continue;
    }
    if (replan_revised(c, t, said, in.text)) round.done.push_back("Revised " + v.id + ".");
    else v.asset = before;  // a bigger vehicle that does not fit stays what it was
  }
  if (!changed_any && revise_count(c, in, targets, round)) return;
  if (!changed_any)
    c.unresolved.push_back({{"instruction", in.text}, {"reason", "found nothing to change (colour, type, placement, speed or action)"}});
  c.last_ref = targets.back();
  if (targets.size() > 1) c.last_group = targets;
}

// A revised vehicle's new motion: what was said over what it had, from where it starts unless the
// revision moves it.
bool Manager::replan_revised(Conversation& c, int t, const json& said, const std::string& text) {
  AddedVehicle& v = c.added[size_t(t)];
  json keep = said;
  // "make it follow the grey car": it keeps its start and follows; only "put it behind the grey
  // car" moves it.
  const bool follow_only = said.contains("relative") && said.value("chase", false);
  if (follow_only) keep.erase("relative");
  if (said.contains("distance_change_m")) {  // "10 m further away"
    keep["distance_m"] = std::max(0.0, v.resolved.value("distance_m", 0.0) + said["distance_change_m"].get<double>());
    keep.erase("distance_change_m");
    keep.erase("relative");
  }
  if (said.contains("distance_factor")) {  // "twice as far away"
    keep["distance_m"] = v.resolved.value("distance_m", 0.0) * said["distance_factor"].get<double>();
    keep.erase("distance_factor");
    keep.erase("relative");
  }
  // Moved along the road: no longer placed by another vehicle, and a side becomes that side ahead.
  json base = v.intent;
  if (said.contains("distance_change_m") || said.contains("distance_factor")) {
    base.erase("relative");
    const std::string side = base.value("placement", v.resolved.value("placement", ""));
    if (side == "left" || side == "right") keep["placement"] = side + "_front";
  }
  // Same place unless told otherwise: a revision of how it moves keeps where it starts.
  const bool place_said = keep.contains("placement") || keep.contains("relative") || keep.contains("distance_m") ||
                          keep.contains("lane_use") || keep.contains("lane");  // "no, in the car park"
  const bool keeps_start = !place_said && !v.intent.contains("relative") && v.resolved.contains("distance_m");
  if (keeps_start) keep["distance_m"] = v.resolved["distance_m"];
  json args{{"base_intent", base}, {"intent", keep}, {"size_lwh", v.asset["size_lwh"]},
            {"type", v.asset["type"]}, {"removed", c.removed}, {"others", others_json(c, t)}};
  // Placed by another vehicle and not moved now: "have it pull out" starts where it stands, not
  // wherever the relation would put a vehicle that moves.
  const json placed_by = base.value("relative", json());
  const bool pinned = !place_said && !follow_only && !placed_by.is_null() && !v.trajectory.empty();
  const json merged_rel = said.contains("relative") ? said["relative"] : (said.contains("placement") ? json() : placed_by);
  const json unpinned = args;
  if (pinned) {
    const auto& p0 = v.trajectory.front();
    args["base_intent"].erase("relative");
    args["intent"]["relative"] = {{"to", v.id}, {"region", "at"}};
    args["anchor"] = {{"id", v.id}, {"x", p0["x"]}, {"y", p0["y"]}, {"yaw", p0["yaw"]}, {"size_lwh", v.asset["size_lwh"]},
                      {"speed_mps", v.speed_mps}, {"wrong_way", v.resolved.value("wrong_way", false)}};
  } else if (!merged_rel.is_null()) {
    if (const auto anchor = find_anchor(c, merged_rel.value("to", "it"), t)) {
      args["anchor"] = *anchor;
      if (follow_only) args["base_intent"].erase("relative");
    } else {
      // The anchor is gone: keep the vehicle where it starts now.
      args["base_intent"].erase("relative");
      args["intent"].erase("relative");
    }
  }
  const size_t unresolved_before = c.unresolved.size();
  bool planned = plan_motion(c, v, args, text);
  if (!planned && (keeps_start || pinned)) {
    // Where it starts was ours to keep, not the user's: "make it go slower" may need a start
    // where the traffic behind does not catch up with it, "drive off" one it can pull out of.
    c.unresolved.erase(c.unresolved.begin() + long(unresolved_before), c.unresolved.end());
    args["intent"].erase("distance_m");
    if (pinned) {
      args = unpinned;
      if (const auto anchor = find_anchor(c, placed_by.value("to", "it"), t)) args["anchor"] = *anchor;
      else args["base_intent"].erase("relative");
    }
    planned = plan_motion(c, v, args, text);
    if (planned) c.notes.push_back(v.id + ": starts at a new place (" + v.resolved.value("distance_m", json(0)).dump() +
                                   " m away): from its old start the revised motion would meet other traffic");
  }
  if (planned && pinned && v.intent.contains("relative") && v.intent["relative"].value("region", "") == "at")
    v.intent["relative"] = placed_by;  // later rounds place it by what placed it
  return planned;
}

void Manager::do_remove_added(Conversation& c, const Instruction& in, Round& round) {
  auto targets = resolve(c, in.target.empty() ? reference_in(in.text) : in.target);
  if (targets.empty()) {  // "delete both parked cars" with nothing added: recorded ones are meant
    do_delete(c, {"delete", in.text, "", 1}, round);
    return;
  }
  std::sort(targets.rbegin(), targets.rend());
  for (int t : targets) {
    round.done.push_back("Removed " + c.added[size_t(t)].id + ".");
    c.added.erase(c.added.begin() + t);
  }
  c.last_ref = c.added.empty() ? -1 : int(c.added.size()) - 1;
  c.last_group.clear();
}

json Manager::edit_state(const Conversation& c) const {
  const auto scene = cached_scene(c.scene_dir);
  json added = json::array();
  for (const auto& v : c.added) {
    json intent = v.resolved;
    intent["lane"] = v.lane;
    intent["speed_mps"] = v.speed_mps;
    added.push_back({{"id", v.id}, {"asset", v.asset["asset"]}, {"type", v.asset["type"]},
                     {"category", v.asset["category"]}, {"brand_words", v.asset["brand_words"]},
                     {"color_rgb", v.asset["color_rgb"]}, {"size_lwh", v.asset["size_lwh"]},
                     {"trajectory", v.trajectory}, {"intent", intent}});
  }
  json view = c.view.empty() ? json{{"translation_m", {0, 0, 0}}, {"yaw_deg", 0}, {"pitch_deg", 0}, {"ego_motion", "none"}}
                             : c.view;
  return {{"scene", scene->name}, {"view", view},      {"removed", c.removed}, {"added", added},
          {"rounds", c.rounds},   {"unresolved", c.unresolved}, {"notes", c.notes}};
}

}  // namespace chatsim::agents::manager
