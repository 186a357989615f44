#include "common/bag/recorded_exchanges.hpp"

#include <map>

#include "common/bag/mcap_reader.hpp"
#include "common/bus/message.hpp"
#include "common/bus/topics.hpp"

namespace chatsim::bag {

std::vector<agents::RecordedExchange> recorded_exchanges(const std::filesystem::path& file, const std::string& kind) {
  const McapReader reader(file);
  const std::string request_topic = bus::topics::agent_request(kind);
  std::map<std::string, agents::AgentCall> requests;  // by correlation id
  std::vector<agents::RecordedExchange> out;
  reader.for_each([&](const McapMessage& m) {
    if (m.channel->message_encoding != "flatbuffer") return;
    flatbuffers::Verifier verifier(reinterpret_cast<const uint8_t*>(m.data.data()), m.data.size());
    if (!msgs::VerifyEnvelopeBuffer(verifier)) return;
    const auto* env = msgs::GetEnvelope(m.data.data());
    const std::string correlation(bus::view(env->header()->correlation_id()));
    if (m.channel->topic == request_topic) {
      if (const auto* r = env->payload_as_AgentRequest()) {
        agents::AgentCall call{std::string(bus::view(r->action())), std::string(bus::view(r->scene())),
                               nlohmann::json::object()};
        if (!bus::view(r->args_json()).empty()) call.args = nlohmann::json::parse(bus::view(r->args_json()), nullptr, false);
        requests[correlation] = call;
      }
      return;
    }
    const auto* resp = env->payload_as_AgentResponse();
    const auto req = requests.find(correlation);
    if (resp == nullptr || req == requests.end()) return;
    agents::AgentOutcome outcome;
    if (resp->ok()) {
      outcome = agents::AgentOutcome::success(nlohmann::json::parse(bus::view(resp->result_json()), nullptr, false));
    } else {
      const auto code = resp->error() ? resp->error()->code() : msgs::ErrorCode::Internal;
      outcome = agents::AgentOutcome::failure(
          code == msgs::ErrorCode::BadRequest ? agents::ErrorKind::BadRequest
          : code == msgs::ErrorCode::NotImplemented ? agents::ErrorKind::NotImplemented
          : code == msgs::ErrorCode::Unavailable ? agents::ErrorKind::Unavailable
                                                 : agents::ErrorKind::Internal,
          resp->error() ? std::string(bus::view(resp->error()->message())) : "failed");
    }
    out.push_back({req->second, outcome});
    requests.erase(req);
  });
  return out;
}

}  // namespace chatsim::bag
