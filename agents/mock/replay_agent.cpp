#include "agents/mock/replay_agent.hpp"

namespace chatsim::agents {

ReplayAgent::Key ReplayAgent::key_of(const AgentCall& call) {
  return {call.action, call.scene, call.args.dump()};  // nlohmann dumps objects with sorted keys
}

ReplayAgent::ReplayAgent(std::string kind, const std::vector<RecordedExchange>& exchanges) : kind_(std::move(kind)) {
  for (const auto& e : exchanges) answers_[key_of(e.request)].push_back(e.response);
}

AgentOutcome ReplayAgent::handle(const AgentCall& call) {
  const Key key = key_of(call);
  const auto it = answers_.find(key);
  if (it == answers_.end())
    return AgentOutcome::failure(ErrorKind::Unavailable, "the recording has no " + kind_ + " request '" + call.action +
                                                             "' with these arguments; record a run that made it");
  size_t& n = used_[key];
  const AgentOutcome& out = it->second[std::min(n, it->second.size() - 1)];  // repeats reuse the last answer
  ++n;
  return out;
}

}  // namespace chatsim::agents
