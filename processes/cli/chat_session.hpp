#pragma once
// One conversation with the manager over the bus (started privately when no bus runs): rounds
// in, results out, with the progress the agents publish shown as it arrives.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "processes/agent_liveness.hpp"
#include "processes/cli/process_graph.hpp"

namespace chatsim::bus {
class Node;
}
namespace chatsim {
class ProgressBar;
}

namespace chatsim::cli {

// Every agent process a rendered round needs.
extern const std::vector<std::string> kAllAgents;

// The folder a conversation's rendered rounds go into (round-N below it), made before any
// process starts: new, empty, or one chatsim made for results (common/util/output_dir.hpp), and
// neither the scene nor a folder holding it. Throws OutputDirError. `option` names it in messages.
std::filesystem::path prepare_rounds_root(const std::string& root, const std::string& scene, bool force,
                                          const std::string& option = "--out-root");
inline constexpr const char* kRoundsRootHelp =
    "folder for the rounds' results (round-N in it): new, empty, or one chatsim made for results; any other folder is "
    "refused";

class ChatSession {
 public:
  // stage, fraction 0..1, message; default: progress bars on stderr.
  using Progress = std::function<void(const std::string&, double, const std::string&)>;
  ChatSession(const std::string& bus, const std::string& scene, std::string conversation, Progress progress = {});
  ~ChatSession();

  struct Outcome {
    bool ok = false;
    std::string message;          // the manager's answer, or why the round failed
    nlohmann::json edit_state;
    std::string output_dir;       // empty when not rendered
  };
  // One round; renders into out when it is not empty (a new or empty folder, or a result chatsim
  // wrote; with force_output, any output chatsim wrote), with a rendering preset (draft, fast or
  // quality; empty: fast).
  Outcome round(const std::string& command, const std::string& out, double timeout_s, const std::string& preset = "",
                bool force_output = false);
  bool lost() const { return lost_; }
  const std::string& conversation() const { return conversation_; }

 private:
  void show(const std::string& stage, double fraction, const std::string& message);
  ProcessGraph graph_;
  std::string scene_, conversation_;
  Progress progress_;
  std::unique_ptr<bus::Node> node_;
  // Six beats, at least 3 s: a manager on a loaded 2-core machine (workers training beside it)
  // has missed three beats and been taken for dead; a crashed one is still named in seconds.
  processes::AgentLiveness liveness_{6.0, 3.0};
  std::unique_ptr<ProgressBar> bar_;
  std::string stage_;
  bool lost_ = false;
  // Progress shows only while a round waits: the answer comes straight to this node's inbox
  // and can overtake the round's last progress reports, which cross the proxy.
  bool in_round_ = false;
};

}  // namespace chatsim::cli
