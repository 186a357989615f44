#pragma once
// The request/response pairs of one agent kind in a recording (requests on
// /agent/<kind>/request, answers on the requester's reply topic, paired by correlation id).
#include <filesystem>
#include <string>
#include <vector>

#include "agents/mock/replay_agent.hpp"

namespace chatsim::bag {

std::vector<agents::RecordedExchange> recorded_exchanges(const std::filesystem::path& mcap, const std::string& kind);

}  // namespace chatsim::bag
