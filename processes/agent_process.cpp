#include "processes/agent_process.hpp"

#include <malloc.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <thread>

#include <spdlog/spdlog.h>

#include "agents/core/agent_registry.hpp"
#include "agents/render/render_agents.hpp"
#include "processes/agent_liveness.hpp"
#include "common/bus/endpoint.hpp"
#include "common/bus/errors.hpp"
#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/util/clock.hpp"
#include "common/util/exit_codes.hpp"
#include "common/util/path_policy.hpp"
#include "common/util/log.hpp"
#include "common/util/signals.hpp"

namespace chatsim::processes {
namespace {

msgs::ErrorCode to_code(agents::ErrorKind kind) {
  switch (kind) {
    case agents::ErrorKind::NotImplemented: return msgs::ErrorCode::NotImplemented;
    case agents::ErrorKind::BadRequest: return msgs::ErrorCode::BadRequest;
    case agents::ErrorKind::Unavailable: return msgs::ErrorCode::Unavailable;
    case agents::ErrorKind::Internal: return msgs::ErrorCode::Internal;
  }
  return msgs::ErrorCode::Internal;
}

bus::Node::Reply wrong_payload(flatbuffers::FlatBufferBuilder& fbb, const std::string& node,
                               const char* expected) {
  return {msgs::Payload::Error,
          bus::make_error(fbb, msgs::ErrorCode::BadRequest, std::string("expected ") + expected, node)
              .Union()};
}

flatbuffers::Offset<msgs::Error> error_of(flatbuffers::FlatBufferBuilder& fbb,
                                          const agents::AgentOutcome& out, const std::string& node) {
  return out.ok ? flatbuffers::Offset<msgs::Error>()
                : bus::make_error(fbb, to_code(out.error), out.message, node);
}

// /agent/<kind>/request: AgentRequest in, AgentResponse out. A malformed args_json is the
// caller's fault, said so.
// Paths in a request must lie inside the allowed folders (when any are configured).
std::optional<agents::AgentOutcome> refuse_paths(const PathPolicy& policy, const agents::AgentCall& call) {
  if (auto why = policy.refuse("scene", call.scene))
    return agents::AgentOutcome::failure(agents::ErrorKind::BadRequest, *why);
  // Every file path a request may carry: results, rendering stages (in, out) and the model.
  for (const char* key : {"output_dir", "in", "out", "model"})
    if (call.args.is_object() && call.args.contains(key) && call.args[key].is_string() && !call.args[key].get<std::string>().empty())
      if (auto why = policy.refuse(key, call.args[key].get<std::string>()))
        return agents::AgentOutcome::failure(agents::ErrorKind::BadRequest, *why);
  return std::nullopt;
}

bus::Node::Reply answer_agent_request(agents::Agent& agent, const PathPolicy& policy, const std::string& node,
                                      const bus::Message& request, flatbuffers::FlatBufferBuilder& fbb) {
  const auto* req = request.payload<msgs::AgentRequest>();
  if (req == nullptr) return wrong_payload(fbb, node, "an AgentRequest");
  agents::AgentCall call{std::string(bus::view(req->action())), std::string(bus::view(req->scene())),
                         nlohmann::json::object()};
  agents::AgentOutcome out;
  try {
    if (!bus::view(req->args_json()).empty()) call.args = nlohmann::json::parse(bus::view(req->args_json()));
    if (auto refused = refuse_paths(policy, call)) out = *refused;
    else out = agent.handle(call);
  } catch (const nlohmann::json::parse_error& e) {
    out = agents::AgentOutcome::failure(agents::ErrorKind::BadRequest,
                                        std::string("args_json is not valid JSON: ") + e.what());
  }
  const auto error = error_of(fbb, out, node);
  const auto resp = msgs::CreateAgentResponseDirect(fbb, agent.kind().c_str(), call.action.c_str(), out.ok,
                                                    out.ok ? out.result.dump().c_str() : nullptr, error);
  return {msgs::Payload::AgentResponse, resp.Union()};
}

// The conversation a process is working for (progress messages carry it).
std::string& current_conversation() {
  static std::string id;
  return id;
}

// /chat/request (the manager only): ChatRequest in, ChatResponse out.
bus::Node::Reply answer_chat_request(agents::Agent& agent, const PathPolicy& policy, const std::string& node,
                                     const bus::Message& request, flatbuffers::FlatBufferBuilder& fbb) {
  const auto* req = request.payload<msgs::ChatRequest>();
  if (req == nullptr) return wrong_payload(fbb, node, "a ChatRequest");
  const std::string conversation(bus::view(req->conversation_id()));
  current_conversation() = conversation;
  const agents::AgentCall call{"chat", std::string(bus::view(req->scene())),
                               {{"command", bus::view(req->command())},
                                {"conversation_id", conversation},
                                {"render", req->render()},
                                {"output_dir", bus::view(req->output_dir())},
                                {"preset", bus::view(req->preset())},
                                {"force_output", req->force_output()}}};
  const auto refused = refuse_paths(policy, call);
  const auto out = refused ? *refused : agent.handle(call);
  const auto error = error_of(fbb, out, node);
  const std::string message = out.ok ? out.result.value("message", std::string()) : out.message;
  const std::string edit = out.ok && out.result.contains("edit_state") ? out.result["edit_state"].dump() : "";
  const std::string output_dir = out.ok ? out.result.value("output_dir", std::string()) : "";
  const auto resp = msgs::CreateChatResponseDirect(fbb, conversation.c_str(), out.ok, message.c_str(),
                                                   edit.c_str(), output_dir.c_str(), error);
  return {msgs::Payload::ChatResponse, resp.Union()};
}

}  // namespace

void add_node_options(CLI::App& app, AgentProcessOptions& o) {
  app.add_option("--bus", o.bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  app.add_option("--name", o.name, "node name on the bus (default: the agent kind)");
  app.add_option("--heartbeat-ms", o.heartbeat_ms, "heartbeat period in ms")->check(CLI::Range(10, 60000));
  app.add_option("--handshake-timeout-ms", o.handshake_timeout_ms,
                 "how long to wait for the bus proxy at start")->check(CLI::Range(100, 600000));
  app.add_option("--allowed-root", o.allowed_roots,
                 "a folder that scene and output paths in requests must lie in (repeatable; default: any)");
  app.add_option("--curve-keys", o.curve_keys,
                 "CURVE keys folder (bus.pub and <name>.pub/.secret): encrypted, authenticated bus");
}

int parse_or_exit(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return exit_code::kUsage;
  }
  return -1;
}

void watch_heartbeats(bus::Node& node, AgentLiveness& liveness) {
  node.subscribe(std::string(bus::topics::kHeartbeat), [&liveness](const bus::Message& m) {
    if (const auto* hb = m.payload<msgs::Heartbeat>())
      liveness.observe(std::string(bus::view(hb->node())), std::string(bus::view(hb->kind())), hb->pid(),
                       hb->period_ms() / 1000.0, hb->state() == msgs::NodeState::Stopping, mono_s());
  });
}

namespace {

agents::AgentOutcome outcome_of(const std::string& kind, const bus::CallResult& result) {
  if (!result.ok())
    return agents::AgentOutcome::failure(
        agents::ErrorKind::Unavailable,
        result.error == msgs::ErrorCode::Unavailable && result.error_message.find("agent failed") != std::string::npos
            ? result.error_message
            : "the " + kind + " agent did not answer (" + result.error_message + "); is chatsim-" + kind + " running on this bus?");
  if (const auto* err = result.response->payload<msgs::Error>()) {
    std::string why(bus::view(err->message()));
    if (!bus::view(err->cause()).empty()) why += " (" + std::string(bus::view(err->cause())) + ")";
    return agents::AgentOutcome::failure(agents::ErrorKind::Internal, "the " + kind + " agent failed: " + why);
  }
  const auto* resp = result.response->payload<msgs::AgentResponse>();
  if (resp == nullptr)
    return agents::AgentOutcome::failure(agents::ErrorKind::Internal, "the " + kind + " agent sent no AgentResponse");
  if (!resp->ok()) {
    const std::string why = resp->error() != nullptr ? std::string(bus::view(resp->error()->message())) : "no reason given";
    const auto code = resp->error() != nullptr ? resp->error()->code() : msgs::ErrorCode::Internal;
    const auto kind_of = code == msgs::ErrorCode::BadRequest       ? agents::ErrorKind::BadRequest
                         : code == msgs::ErrorCode::NotImplemented ? agents::ErrorKind::NotImplemented
                         : code == msgs::ErrorCode::Unavailable    ? agents::ErrorKind::Unavailable
                                                                   : agents::ErrorKind::Internal;
    return agents::AgentOutcome::failure(kind_of, why);
  }
  try {
    return agents::AgentOutcome::success(nlohmann::json::parse(bus::view(resp->result_json())));
  } catch (const nlohmann::json::parse_error& e) {
    return agents::AgentOutcome::failure(agents::ErrorKind::Internal, "the " + kind + " agent answered malformed JSON: " + e.what());
  }
}

// An agent started along with the manager may not have sent its first heartbeat yet; a request
// sent before it subscribed would be lost and the caller would wait out the whole deadline.
constexpr auto kAgentStartGrace = std::chrono::seconds(15);

bool await_agent(bus::Node& node, const AgentLiveness& liveness, const std::string& kind) {
  return node.wait_until([&] { return !liveness.snapshot(kind, mono_s()).empty(); }, kAgentStartGrace);
}

std::string no_agent_message(const std::string& kind) {
  return "no chatsim-" + kind + " process is running on this bus (none sent a heartbeat within " +
         std::to_string(kAgentStartGrace.count()) + " s); start it or check --bus";
}

}  // namespace

agents::manager::AgentCaller bus_caller(bus::Node& node, std::chrono::milliseconds timeout,
                                        const AgentLiveness* liveness) {
  return [&node, timeout, liveness](const std::string& kind, const agents::AgentCall& call) {
    flatbuffers::FlatBufferBuilder fbb(1024);
    const auto req = msgs::CreateAgentRequestDirect(fbb, kind.c_str(), call.action.c_str(), call.scene.c_str(),
                                                    call.args.dump().c_str());
    std::function<std::optional<std::string>()> give_up;
    std::string topic = bus::topics::agent_request(kind);
    if (liveness != nullptr) {
      if (!await_agent(node, *liveness, kind))
        return agents::AgentOutcome::failure(agents::ErrorKind::Unavailable, no_agent_message(kind));
      auto sent_to = liveness->snapshot(kind, mono_s());
      // Several processes of this kind (workers): ask one, not all of them.
      if (sent_to.size() > 1) {
        sent_to.resize(1);
        topic = bus::topics::agent_worker_request(kind, sent_to.front().node);
      }
      give_up = [liveness, kind, sent_to] { return liveness->lost(kind, sent_to, mono_s()); };
    }
    const auto wait = call.timeout_s > 0 ? std::chrono::milliseconds(int64_t(call.timeout_s * 1000)) : timeout;
    return outcome_of(kind, node.call(topic, fbb, msgs::Payload::AgentRequest, req.Union(), wait, give_up));
  };
}

agents::manager::FanoutCaller bus_fanout_caller(bus::Node& node, std::chrono::milliseconds timeout, const AgentLiveness& liveness) {
  return [&node, timeout, &liveness](const std::string& kind, const std::vector<agents::AgentCall>& calls) {
    std::vector<agents::AgentOutcome> out(calls.size());
    std::vector<size_t> pending(calls.size());
    for (size_t i = 0; i < calls.size(); ++i) pending[i] = i;
    std::vector<int> attempts(calls.size(), 0);
    while (!pending.empty()) {
      if (!await_agent(node, liveness, kind)) {
        for (size_t i : pending) out[i] = agents::AgentOutcome::failure(agents::ErrorKind::Unavailable, no_agent_message(kind));
        break;
      }
      const auto workers = liveness.snapshot(kind, mono_s());
      // One wave: a call per worker.
      const size_t n = std::min(workers.size(), pending.size());
      std::vector<flatbuffers::FlatBufferBuilder> fbbs(n);
      std::vector<bus::Node::Request> requests(n);
      double wait_s = 0;
      for (size_t k = 0; k < n; ++k) {
        const auto& call = calls[pending[k]];
        const auto req = msgs::CreateAgentRequestDirect(fbbs[k], kind.c_str(), call.action.c_str(), call.scene.c_str(),
                                                        call.args.dump().c_str());
        const std::vector<AgentLiveness::Instance> sent_to{workers[k]};
        requests[k] = {bus::topics::agent_worker_request(kind, workers[k].node), &fbbs[k], msgs::Payload::AgentRequest,
                       req.Union(), [&liveness, kind, sent_to] { return liveness.lost(kind, sent_to, mono_s()); }};
        wait_s = std::max(wait_s, call.timeout_s);
      }
      const auto wait = wait_s > 0 ? std::chrono::milliseconds(int64_t(wait_s * 1000)) : timeout;
      const auto results = node.call_many(requests, wait);
      std::vector<size_t> again;
      for (size_t k = 0; k < n; ++k) {
        const size_t i = pending[k];
        const bool worker_lost = !results[k].ok() && results[k].error == msgs::ErrorCode::Unavailable;
        if (worker_lost && ++attempts[i] < 3) {
          spdlog::warn("{} worker '{}' was lost ({}); giving its work to another", kind, workers[k].node, results[k].error_message);
          again.push_back(i);
          continue;
        }
        out[i] = outcome_of(kind, results[k]);
      }
      again.insert(again.end(), pending.begin() + long(n), pending.end());
      pending = again;
    }
    return out;
  };
}

namespace {

// A request handler can run for minutes (rendering) and only returns to the loop that checks
// for signals when it is done. The watchdog keeps the promise to stop within a second of
// SIGINT/SIGTERM anyway: it leaves without finishing the request, which is safe because every
// output is written under a temporary name and renamed when complete.
class StopWatchdog {
 public:
  explicit StopWatchdog(const std::atomic<bool>& stop)
      : thread_([this, &stop] {
          using namespace std::chrono_literals;
          while (!stop.load() && !finished_.load()) std::this_thread::sleep_for(20ms);
          // The request may finish until a deadline 0.8 s after the signal is seen. Counting
          // sleeps instead (45 of 20 ms) overshot the second under load: each sleep runs late.
          const auto deadline = std::chrono::steady_clock::now() + 800ms;
          while (!finished_.load() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(10ms);
          if (finished_.load()) return;
          spdlog::warn("stopping in the middle of a request (signal {}): its outputs are left unwritten", stop_signal());
          spdlog::default_logger()->flush();
          std::_Exit(exit_code::kOk);
        }) {}
  ~StopWatchdog() {
    left_loop();
    thread_.join();
  }
  // The serving loop has returned: shutting down from here on is quick and needs no watchdog.
  void left_loop() { finished_.store(true); }

 private:
  std::atomic<bool> finished_{false};
  std::thread thread_;
};

}  // namespace

int serve_agent(const AgentProcessOptions& options, const std::string& kind, const AgentFactory& make) {
  const auto& stop = install_stop_signals();
  StopWatchdog watchdog(stop);
  bus::NodeOptions no;
  no.kind = kind;
  no.name = options.name.empty() ? no.kind : options.name;
  no.bus = options.bus.empty() ? bus::default_bus_endpoint() : options.bus;
  no.heartbeat_period = std::chrono::milliseconds(options.heartbeat_ms);
  no.handshake_timeout = std::chrono::milliseconds(options.handshake_timeout_ms);
  init_logging(no.name);
  if (!options.curve_keys.empty()) {
    try {
      no.curve = bus::curve_client_from_dir(options.curve_keys, no.name);
    } catch (const std::exception& e) {
      spdlog::error("{}", e.what());
      return exit_code::kUsage;
    }
  }
  const PathPolicy policy(std::vector<std::filesystem::path>(options.allowed_roots.begin(), options.allowed_roots.end()));
  try {
    bus::Node node(no);
    auto agent = make(node);
    const auto answer = [&](const bus::Message& request, flatbuffers::FlatBufferBuilder& fbb) {
      const double t0 = mono_s();
      auto reply = answer_agent_request(*agent, policy, no.name, request, fbb);
      // A rendering job frees hundreds of MB of images from many threads' arenas: give it back
      // to the system, so a long-running agent's size shows what it holds, not its peak.
      if (mono_s() - t0 > 0.2) malloc_trim(0);
      return reply;
    };
    node.serve(bus::topics::agent_request(no.kind), answer);
    // Its own topic too, so a manager can spread work over several processes of one kind.
    node.serve(bus::topics::agent_worker_request(no.kind, no.name), answer);
    if (no.kind == "manager") {
      node.serve(std::string(bus::topics::kChatRequest),
                 [&](const bus::Message& request, flatbuffers::FlatBufferBuilder& fbb) {
                   return answer_chat_request(*agent, policy, no.name, request, fbb);
                 });
    }
    node.start();
    spdlog::info("'{}' ({}) serving on bus {}", no.name, no.kind, no.bus);
    node.spin(stop);
    watchdog.left_loop();
    spdlog::info("stopping (signal {})", stop_signal());
    node.shutdown();
  } catch (const bus::BusError& e) {
    spdlog::error("{}", e.what());
    return exit_code::kBusUnavailable;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return exit_code::kUsage;
  }
  return exit_code::kOk;
}

agents::render::PipelineProgress progress_publisher(bus::Node& node) {
  return [&node](const std::string& stage, double fraction, const std::string& message) {
    flatbuffers::FlatBufferBuilder fbb(256);
    const auto p = msgs::CreateChatProgressDirect(fbb, current_conversation().c_str(), stage.c_str(), float(fraction), message.c_str());
    node.publish(bus::topics::kChatProgress, fbb, msgs::Payload::ChatProgress, p.Union());
  };
}

int agent_main(int argc, char** argv, const std::string& kind) {
  const auto* info = agents::find_agent_kind(kind);
  CLI::App app(info != nullptr ? info->process + ": " + info->role : kind);
  AgentProcessOptions options;
  add_node_options(app, options);
  if (const int code = parse_or_exit(app, argc, argv); code >= 0) return code;
  auto liveness = std::make_shared<AgentLiveness>();
  return serve_agent(options, kind, [&, liveness](bus::Node& node) -> std::unique_ptr<agents::Agent> {
    if (auto rendering = agents::render::make_render_agent(kind, progress_publisher(node))) return rendering;
    if (kind != "manager") return agents::make_agent(kind);
    // The manager reaches the other agents over the bus; an answer may take a while, but a
    // dead agent is noticed from its heartbeats within seconds.
    watch_heartbeats(node, *liveness);
    return agents::render::make_rendering_manager(bus_caller(node, std::chrono::seconds(60), liveness.get()),
                                                  progress_publisher(node),
                                                  bus_fanout_caller(node, std::chrono::seconds(3600), *liveness));
  });
}

}  // namespace chatsim::processes
