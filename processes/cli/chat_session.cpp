#include "processes/cli/chat_session.hpp"

#include <unistd.h>

#include <filesystem>
#include <iostream>

#include <spdlog/spdlog.h>

#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "common/util/output_dir.hpp"
#include "common/util/progress.hpp"
#include "processes/agent_process.hpp"

namespace chatsim::cli {
namespace fs = std::filesystem;

const std::vector<std::string> kAllAgents{"manager", "view", "background", "deletion", "asset", "motion", "foreground"};

ChatSession::ChatSession(const std::string& bus, const std::string& scene, std::string conversation, Progress progress)
    : graph_(bus, kAllAgents), scene_(scene), conversation_(std::move(conversation)), progress_(std::move(progress)) {
  bus::NodeOptions o;
  o.name = "chat-" + std::to_string(getpid());
  o.kind = "cli";
  o.curve = bus::curve_client_from_env();
  o.bus = graph_.endpoint();
  o.heartbeat_period = std::chrono::milliseconds(0);
  node_ = std::make_unique<bus::Node>(o);
  processes::watch_heartbeats(*node_, liveness_);
  node_->subscribe(std::string(bus::topics::kChatProgress), [this](const bus::Message& m) {
    const auto* p = m.payload<msgs::ChatProgress>();
    if (p == nullptr) return;
    const std::string conv(bus::view(p->conversation_id()));
    if (!in_round_ || (!conv.empty() && conv != conversation_)) return;  // late, or someone else's round
    show(std::string(bus::view(p->stage())), p->fraction(), std::string(bus::view(p->message())));
  });
  node_->dispatch_during_calls(std::string(bus::topics::kChatProgress));
  node_->start();
  for (const double until = mono_s() + 2.0; mono_s() < until && liveness_.snapshot("manager", mono_s()).empty();)
    node_->spin_once(std::chrono::milliseconds(20));
  if (conversation_.empty()) conversation_ = o.name;
}

ChatSession::~ChatSession() {
  if (bar_) bar_->finish();
  if (node_) node_->shutdown();
}

void ChatSession::show(const std::string& stage, double fraction, const std::string& message) {
  if (progress_) {
    progress_(stage, fraction, message);
    return;
  }
  if (!bar_ || stage != stage_) {
    if (bar_) bar_->finish();
    bar_ = std::make_unique<ProgressBar>(stage);
    stage_ = stage;
  }
  bar_->update(fraction, message);
}

fs::path prepare_rounds_root(const std::string& root, const std::string& scene, bool force, const std::string& option) {
  refuse_output_over_input(root, scene, option, "--scene");
  return prepare_output_root(root, "results", force, option);
}

ChatSession::Outcome ChatSession::round(const std::string& command, const std::string& out, double timeout_s,
                                        const std::string& preset, bool force_output) {
  Outcome result;
  flatbuffers::FlatBufferBuilder fbb(1024);
  const std::string out_abs = out.empty() ? "" : fs::absolute(out).lexically_normal().string();
  const auto req = msgs::CreateChatRequestDirect(fbb, conversation_.c_str(), scene_.c_str(), command.c_str(), !out.empty(),
                                                 out_abs.c_str(), preset.c_str(), force_output);
  const auto sent_to = liveness_.snapshot("manager", mono_s());
  show("decisions", 0, "the agents decide");
  in_round_ = true;
  const auto r = node_->call(bus::topics::kChatRequest, fbb, msgs::Payload::ChatRequest, req.Union(),
                             std::chrono::milliseconds(int64_t(timeout_s * 1000)),
                             [&] { return liveness_.lost("manager", sent_to, mono_s()); });
  in_round_ = false;
  if (bar_) bar_->finish();
  bar_.reset();
  if (!r.ok()) {
    result.message = "no answer from the manager: " + r.error_message;
    lost_ = true;
    return result;
  }
  const auto* resp = r.response->payload<msgs::ChatResponse>();
  if (resp == nullptr || !resp->ok()) {
    result.message = resp && resp->error() ? std::string(bus::view(resp->error()->message())) : "the manager failed";
    return result;
  }
  result.ok = true;
  result.message = std::string(bus::view(resp->message()));
  if (!bus::view(resp->edit_state_json()).empty()) result.edit_state = nlohmann::json::parse(bus::view(resp->edit_state_json()));
  result.output_dir = std::string(bus::view(resp->output_dir()));
  return result;
}

}  // namespace chatsim::cli
