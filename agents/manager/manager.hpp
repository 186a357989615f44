#pragma once
// The project manager: decomposes each command, routes the instructions to the view, deletion,
// asset and motion agents (through a caller, so the same logic runs in-process or over the bus),
// resolves references across rounds, and keeps each conversation's edit state.
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agents/core/agent.hpp"
#include "agents/llm/llm_backend.hpp"
#include "agents/manager/decompose.hpp"

namespace chatsim::agents::manager {

using AgentCaller = std::function<AgentOutcome(const std::string& kind, const AgentCall& call)>;
// Several calls to one kind at once, spread over the live processes of that kind (workers);
// answers in the calls' order.
using FanoutCaller = std::function<std::vector<AgentOutcome>(const std::string& kind, const std::vector<AgentCall>& calls)>;

struct AddedVehicle {
  std::string id;
  nlohmann::json asset;        // asset agent's choice
  nlohmann::json intent;       // what was said, merged over rounds (motion intent)
  nlohmann::json resolved;     // the intent as planned, every default filled in
  nlohmann::json trajectory;   // [{t_s, x, y, yaw}]
  double speed_mps = 0;
  std::string lane;
};

struct Conversation {
  std::string scene_dir;
  nlohmann::json view = nlohmann::json::object();
  std::vector<std::string> removed;
  std::vector<std::vector<std::string>> removal_batches;  // for "put back the deleted car"
  std::vector<AddedVehicle> added;
  nlohmann::json rounds = nlohmann::json::array();
  nlohmann::json unresolved = nlohmann::json::array();
  nlohmann::json notes = nlohmann::json::array();
  int next_id = 1;
  int last_ref = -1;           // the vehicle "it" means
  std::vector<int> last_group; // the vehicles "them"/"both" mean
  // Recorded vehicles something was placed relative to, by id: later rounds find the same one.
  std::map<std::string, nlohmann::json> recorded_anchors;
  // The state before each of the last rounds, newest last: what "undo that" goes back to.
  std::vector<std::shared_ptr<const Conversation>> undo;
};

struct ChatResult {
  nlohmann::json edit_state;
  std::string message;         // one paragraph for the user: what was done, what was not
};

class Manager {
 public:
  static constexpr int kMaxAddedPerInstruction = 40;
  // Conversations kept; the least recently used beyond this are forgotten (bounded memory).
  static constexpr size_t kMaxConversations = 64;
  // Rounds "undo" can go back, one at a time.
  static constexpr size_t kUndoDepth = 16;

  Manager(AgentCaller caller, std::shared_ptr<llm::Backend> backend);

  // One round of a conversation. Throws std::runtime_error for a bad scene or a failed agent.
  ChatResult chat(const std::string& conversation_id, const std::string& scene_dir, const std::string& command);
  void reset(const std::string& conversation_id);

 private:
  // What one round did: its instructions, a line per change for the user, the vehicles it added.
  struct Round {
    nlohmann::json instructions = nlohmann::json::array();
    std::vector<std::string> done;
    std::vector<int> added_now;
  };
  ChatResult run_round(Conversation& c, const std::string& scene_dir, const std::string& command);
  void run_instruction(Conversation& c, const Instruction& in, Round& round);
  void do_view(Conversation& c, const Instruction& in, Round& round);
  void do_delete(Conversation& c, const Instruction& in, Round& round);
  bool restore_described(Conversation& c, const std::vector<std::string>& words, Round& round);
  void do_restore(Conversation& c, const Instruction& in, Round& round);
  void do_undo(Conversation& c, const Instruction& in, Round& round);
  void remember_for_undo(Conversation& c);
  // Back to the state kept newest in c.undo (which it drops), keeping the rounds said and the unresolved.
  void back_to_round_start(Conversation& c);
  static bool same_again(const Conversation& c, const std::string& command, Instruction& in);
  static void continue_previous_round(const Conversation& c, const std::string& command,
                                      std::vector<Instruction>& instructions);
  bool replaces_last_round(const Conversation& c, const std::string& command,
                           const std::vector<Instruction>& instructions) const;
  void do_add(Conversation& c, const Instruction& in, Round& round);
  void do_revise(Conversation& c, const Instruction& in, Round& round);
  // "swap the bendy bus for a double-decker": a recorded vehicle goes and the new one takes its
  // place; false when the words name no such swap or an added vehicle (replace_recorded.cpp).
  bool replace_recorded(Conversation& c, const Instruction& in, Round& round);
  bool replan_revised(Conversation& c, int index, const nlohmann::json& said, const std::string& text);
  // "make it four" after two cones: as many of the group as said (group_count.cpp).
  bool revise_count(Conversation& c, const Instruction& in, const std::vector<int>& targets, Round& round);
  void do_remove_added(Conversation& c, const Instruction& in, Round& round);
  void do_abstract(Conversation& c, const Instruction& in, Round& round);
  // Asks the motion agent for v's trajectory and stores it; false (and unresolved) when it
  // cannot be planned, an exception when the agent failed.
  bool plan_motion(Conversation& c, AddedVehicle& v, const nlohmann::json& args, const std::string& text);
  bool add_one(Conversation& c, const nlohmann::json& asset_args, const nlohmann::json& motion_args,
               const std::string& text, Round& round, bool strict = false,
               const nlohmann::json* group_anchor = nullptr);
  std::vector<int> resolve(const Conversation& c, const std::string& reference) const;
  // The start of the vehicle a placement is relative to: an added one (not `except`), else a
  // recorded one the deletion agent selects by the same words; nullopt when none matches.
  std::optional<nlohmann::json> find_anchor(Conversation& c, const std::string& reference, int except);
  // "twice as fast as the cyclist": that vehicle's speed, times the factor, as the intent's
  // speed_mps (speed_of.cpp); a vehicle not found is said in the notes.
  void speed_of_vehicle(Conversation& c, nlohmann::json& intent, const std::string& self_id);
  std::optional<nlohmann::json> ordinal_of_removed(Conversation& c, const std::string& reference);
  // "make it the same colour as the coach": the reference's colour said as a word ("white").
  std::string colours_of_references(Conversation& c, const std::string& text);
  nlohmann::json others_json(const Conversation& c, int except) const;
  nlohmann::json edit_state(const Conversation& c) const;
  AgentOutcome call(const std::string& kind, const Conversation& c, const std::string& action, nlohmann::json args);

  AgentCaller caller_;
  std::shared_ptr<llm::Backend> backend_;
  std::mutex mu_;
  std::map<std::string, Conversation> conversations_;
  std::map<std::string, uint64_t> last_used_;  // conversation -> use counter
  uint64_t uses_ = 0;
};

// Renders an edit state into output_dir with a preset (draft, fast or quality; empty: fast) (the
// rendering pipeline; see agents/render); force_output: output_dir may hold a chatsim output of
// another kind. Returns the result's summary, or a failure saying why.
using Renderer = std::function<AgentOutcome(const std::string& scene_dir, const nlohmann::json& edit_state,
                                            const std::string& output_dir, const std::string& preset, bool force_output)>;

// Checks, before any work, the folder a rendered round writes: new, empty or a result chatsim
// wrote (with force, any output chatsim wrote), and neither the scene nor a folder holding it.
// Throws OutputDirError saying what is wrong and the fix.
void check_render_output(const std::string& out, const std::string& scene, bool force);

// The manager as an Agent: action "chat" (args: command, conversation_id, render, output_dir, preset, force_output)
// and "reset". With render true, the round's edit state is rendered by `renderer` (none: the
// manager says it cannot render).
std::unique_ptr<Agent> make_manager_agent(AgentCaller caller, std::shared_ptr<llm::Backend> backend, Renderer renderer = {});

}  // namespace chatsim::agents::manager
