#include <gtest/gtest.h>

#include <filesystem>

#include "agents/mock/mock_script.hpp"

using namespace chatsim::agents;

namespace {

const char* kScript = R"(
agent: motion
seed: 3
responses:
  - match: {action: plan, args_contains: porsche}
    result: {kind: porsche}
  - match: {action: plan}
    result: {kind: generic, n: 2}
  - match: {action: render}
    error: {code: not_implemented, message: no renderer}
)";

}  // namespace

TEST(MockScript, AnswersTheFirstMatchingResponse) {
  MockAgent agent(parse_mock_script(kScript, "m.yaml"));
  EXPECT_EQ(agent.kind(), "motion");
  auto r = agent.handle({"plan", "", {{"asset", "porsche"}}});
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.result["kind"], "porsche");
  r = agent.handle({"plan", "", {{"asset", "van"}}});
  EXPECT_EQ(r.result["kind"], "generic");
  EXPECT_EQ(r.result["n"], 2);
  r = agent.handle({"render", "", {}});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error, ErrorKind::NotImplemented);
  r = agent.handle({"fly", "", {}});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("'fly'"), std::string::npos);
}

TEST(MockScript, FailureInjectionIsSeededAndProportional) {
  auto script = parse_mock_script(kScript, "m.yaml");
  script.failure_rate = 0.3;
  MockAgent a(script), b(script);
  int failures = 0;
  for (int i = 0; i < 1000; ++i) {
    const bool fa = !a.handle({"plan", "", {}}).ok;
    const bool fb = !b.handle({"plan", "", {}}).ok;
    EXPECT_EQ(fa, fb);  // same seed, same sequence
    failures += fa;
  }
  EXPECT_GT(failures, 240);
  EXPECT_LT(failures, 360);
}

TEST(MockScript, BadScriptsNameFileAndLine) {
  auto error = [](const std::string& text) {
    try {
      parse_mock_script(text, "m.yaml");
    } catch (const MockScriptError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("responses: []\n").find("missing 'agent'"), std::string::npos);
  EXPECT_NE(error("agent: a\nresponses:\n  - reslt: {}\n").find("m.yaml:3:5"), std::string::npos);
  EXPECT_NE(error("agent: a\nfailure_rate: 2\nresponses: []\n").find("failure_rate"), std::string::npos);
  EXPECT_NE(error("agent: a\nresponses:\n  - error: {code: oops}\n").find("error code 'oops'"), std::string::npos);
}

TEST(MockScript, ShippedScriptLoads) {
  const auto s = load_mock_script(std::filesystem::path(CHATSIM_SOURCE_DIR) / "launch/mocks/motion.yaml");
  EXPECT_EQ(s.agent, "motion");
  EXPECT_EQ(s.responses.size(), 3u);
}
