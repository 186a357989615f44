#include <gtest/gtest.h>

#include "agents/core/agent_registry.hpp"

using namespace chatsim::agents;

TEST(AgentRegistry, HasTheSevenAgentsOfTheDesign) {
  std::vector<std::string> kinds;
  for (const auto& k : agent_kinds()) kinds.push_back(k.kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"manager", "view", "background", "deletion", "asset",
                                             "motion", "foreground"}));
  EXPECT_THROW(make_agent("painter"), std::invalid_argument);
}

// This registry makes the decision agents; asked for a rendering agent it says where those are
// made instead of inventing a result. Every agent refuses actions it does not have.
TEST(AgentRegistry, MissingCapabilitiesAnswerNotImplemented) {
  for (const auto& k : agent_kinds()) {
    auto agent = make_agent(k.kind);
    const auto out = agent->handle({"no-such-action", "scene", nlohmann::json::object()});
    EXPECT_FALSE(out.ok) << k.kind;
    const bool renderer = k.kind == "background" || k.kind == "foreground";
    EXPECT_EQ(out.error, renderer ? ErrorKind::NotImplemented : ErrorKind::BadRequest) << k.kind;
    if (renderer) {
      EXPECT_NE(out.message.find("agents/render"), std::string::npos) << out.message;
    }
  }
}
