#include "processes/agent_process.hpp"

#include <spdlog/spdlog.h>

#include "agents/core/agent_registry.hpp"
#include "common/bus/endpoint.hpp"
#include "common/bus/errors.hpp"
#include "common/bus/node.hpp"
#include "common/bus/topics.hpp"
#include "common/util/exit_codes.hpp"
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

// Parses args_json; a malformed one is the caller's fault, said so.
agents::AgentOutcome handle(agents::Agent& agent, const std::string& action,
                            const std::string& scene, std::string_view args_json) {
  agents::AgentCall call{action, scene, nlohmann::json::object()};
  if (!args_json.empty()) {
    try {
      call.args = nlohmann::json::parse(args_json);
    } catch (const nlohmann::json::parse_error& e) {
      return agents::AgentOutcome::failure(agents::ErrorKind::BadRequest,
                                           std::string("args_json is not valid JSON: ") + e.what());
    }
  }
  return agent.handle(call);
}

}  // namespace

void add_node_options(CLI::App& app, AgentProcessOptions& o) {
  app.add_option("--bus", o.bus, "bus endpoint (default: $CHATSIM_BUS or tcp://127.0.0.1:7700)");
  app.add_option("--name", o.name, "node name on the bus (default: the agent kind)");
  app.add_option("--heartbeat-ms", o.heartbeat_ms, "heartbeat period in ms")->check(CLI::Range(10, 60000));
  app.add_option("--handshake-timeout-ms", o.handshake_timeout_ms,
                 "how long to wait for the bus proxy at start")->check(CLI::Range(100, 600000));
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

int serve_agent(const AgentProcessOptions& options, std::unique_ptr<agents::Agent> agent) {
  const auto& stop = install_stop_signals();
  bus::NodeOptions no;
  no.kind = agent->kind();
  no.name = options.name.empty() ? no.kind : options.name;
  no.bus = options.bus.empty() ? bus::default_bus_endpoint() : options.bus;
  no.heartbeat_period = std::chrono::milliseconds(options.heartbeat_ms);
  no.handshake_timeout = std::chrono::milliseconds(options.handshake_timeout_ms);
  init_logging(no.name);
  try {
    bus::Node node(no);
    node.serve(bus::topics::agent_request(no.kind),
               [&](const bus::Message& request, flatbuffers::FlatBufferBuilder& fbb) {
                 const auto* req = request.payload<msgs::AgentRequest>();
                 if (req == nullptr) {
                   return bus::Node::Reply{
                       msgs::Payload::Error,
                       bus::make_error(fbb, msgs::ErrorCode::BadRequest,
                                       "expected an AgentRequest", no.name).Union()};
                 }
                 const std::string action(bus::view(req->action()));
                 const auto out = handle(*agent, action, std::string(bus::view(req->scene())),
                                         bus::view(req->args_json()));
                 const auto error = out.ok ? flatbuffers::Offset<msgs::Error>()
                                           : bus::make_error(fbb, to_code(out.error), out.message, no.name);
                 const auto resp = msgs::CreateAgentResponseDirect(
                     fbb, no.kind.c_str(), action.c_str(), out.ok,
                     out.ok ? out.result.dump().c_str() : nullptr, error);
                 return bus::Node::Reply{msgs::Payload::AgentResponse, resp.Union()};
               });
    if (no.kind == "manager") {
      node.serve(std::string(bus::topics::kChatRequest),
                 [&](const bus::Message& request, flatbuffers::FlatBufferBuilder& fbb) {
                   const auto* req = request.payload<msgs::ChatRequest>();
                   if (req == nullptr) {
                     return bus::Node::Reply{
                         msgs::Payload::Error,
                         bus::make_error(fbb, msgs::ErrorCode::BadRequest, "expected a ChatRequest", no.name).Union()};
                   }
                   nlohmann::json args = {{"command", bus::view(req->command())},
                                          {"conversation_id", bus::view(req->conversation_id())},
                                          {"render", req->render()},
                                          {"output_dir", bus::view(req->output_dir())}};
                   const auto out = handle(*agent, "chat", std::string(bus::view(req->scene())), args.dump());
                   const auto error = out.ok ? flatbuffers::Offset<msgs::Error>()
                                             : bus::make_error(fbb, to_code(out.error), out.message, no.name);
                   std::string message = out.ok ? out.result.value("message", std::string()) : out.message;
                   std::string edit = out.ok && out.result.contains("edit_state") ? out.result["edit_state"].dump() : "";
                   const std::string conversation(bus::view(req->conversation_id()));
                   const auto resp = msgs::CreateChatResponseDirect(
                       fbb, conversation.c_str(), out.ok, message.c_str(),
                       edit.c_str(), out.ok ? out.result.value("output_dir", std::string()).c_str() : "",
                       error);
                   return bus::Node::Reply{msgs::Payload::ChatResponse, resp.Union()};
                 });
    }
    node.start();
    spdlog::info("'{}' ({}) serving on bus {}", no.name, no.kind, no.bus);
    node.spin(stop);
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

int agent_main(int argc, char** argv, const std::string& kind) {
  const auto* info = agents::find_agent_kind(kind);
  CLI::App app(info != nullptr ? info->process + ": " + info->role : kind);
  AgentProcessOptions options;
  add_node_options(app, options);
  if (const int code = parse_or_exit(app, argc, argv); code >= 0) return code;
  return serve_agent(options, agents::make_agent(kind));
}

}  // namespace chatsim::processes
