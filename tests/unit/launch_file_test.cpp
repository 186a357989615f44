#include <gtest/gtest.h>

#include <filesystem>

#include "common/launch/launch_file.hpp"

using namespace chatsim::launch;

namespace {

std::string error_of(const std::string& text) {
  try {
    parse_launch_file(text, "test.yaml");
  } catch (const LaunchFileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LaunchFile, ParsesEveryField) {
  const auto f = parse_launch_file(R"(
bus: tcp://127.0.0.1:0
stop_timeout_s: 2
processes:
  - name: bus
    kind: bus
    executable: chatsim-bus
    respawn: always
  - name: motion-1
    kind: motion
    executable: chatsim-motion
    args: [--heartbeat-ms, "200"]
    env: {CHATSIM_LOG_LEVEL: debug}
    host: worker1
    respawn: on-failure
    respawn_delay_s: 0.2
    respawn_max_delay_s: 4
    max_respawns: 3
    ready: none
    ready_timeout_s: 5
  - name: view
    mock: mocks/view.yaml
)", "/x/launch/test.yaml");
  EXPECT_EQ(f.bus, "tcp://127.0.0.1:0");
  EXPECT_DOUBLE_EQ(f.stop_timeout_s, 2);
  ASSERT_EQ(f.processes.size(), 3u);
  const auto& m = f.processes[1];
  EXPECT_EQ(m.kind, "motion");
  EXPECT_EQ(m.args, (std::vector<std::string>{"--heartbeat-ms", "200"}));
  EXPECT_EQ(m.env.at("CHATSIM_LOG_LEVEL"), "debug");
  EXPECT_EQ(m.host, "worker1");
  EXPECT_EQ(m.respawn, RespawnPolicy::OnFailure);
  EXPECT_EQ(m.backoff.max_respawns, 3);
  EXPECT_EQ(m.ready, Readiness::None);
  EXPECT_EQ(m.line, 9);
  EXPECT_EQ(f.processes[2].kind, "view");
  EXPECT_EQ(*f.processes[2].mock_script, std::filesystem::path("/x/launch/mocks/view.yaml"));
}

TEST(LaunchFile, UnknownKeyGivesLineColumnAndSuggestion) {
  const auto e = error_of("bus: tcp://h:1\nprocesses:\n  - name: a\n    executable: x\n    respwn: always\n");
  EXPECT_NE(e.find("test.yaml:5:5"), std::string::npos) << e;
  EXPECT_NE(e.find("respwn"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'respawn'"), std::string::npos) << e;
}

TEST(LaunchFile, RefusesBadValuesWithTheirLocation) {
  EXPECT_NE(error_of("processes:\n  - name: a\n    executable: x\n    respawn: sometimes\n").find("test.yaml:4:14"), std::string::npos);
  EXPECT_NE(error_of("processes:\n  - name: a\n    executable: x\n  - name: a\n    executable: y\n").find("duplicate process name 'a'"), std::string::npos);
  EXPECT_NE(error_of("processes:\n  - name: a\n").find("has no 'executable'"), std::string::npos);
  EXPECT_NE(error_of("processes:\n  - name: a\n    executable: x\n    ready_timeout_s: -1\n").find("ready_timeout_s"), std::string::npos);
  EXPECT_NE(error_of("processes:\n  - name: a\n    executable: x\n    args: --foo\n").find("args must be a list"), std::string::npos);
  EXPECT_NE(error_of("processes: []\n").find("non-empty list"), std::string::npos);
  EXPECT_NE(error_of("bus: [unclosed\n").find("not valid YAML"), std::string::npos);
  EXPECT_NE(error_of("processes:\n  - name: a/b\n    executable: x\n").find("without '/'"), std::string::npos);
}

TEST(LaunchFile, MockSwapNamesMissingProcesses) {
  auto f = parse_launch_file("processes:\n  - name: motion\n    executable: chatsim-motion\n", "t.yaml");
  swap_for_mock(f, "motion", "m.yaml");
  EXPECT_EQ(*f.processes[0].mock_script, std::filesystem::path("m.yaml"));
  try {
    swap_for_mock(f, "asset", "m.yaml");
    FAIL();
  } catch (const LaunchFileError& e) {
    EXPECT_NE(std::string(e.what()).find("it has: motion"), std::string::npos) << e.what();
  }
}

TEST(LaunchFile, ShippedLaunchFilesAreValid) {
  for (const char* name : {"local.yaml", "local-mock-motion.yaml"}) {
    const auto f = load_launch_file(std::filesystem::path(CHATSIM_SOURCE_DIR) / "launch" / name);
    EXPECT_EQ(f.processes.size(), 8u) << name;
  }
}

// Found by fuzzing (fuzz/corpus/launch_file keeps the input): a key that is itself a list.
TEST(LaunchFile, ComplexKeysAreRefusedNotACrash) {
  const std::string text = "bus: tcp://127.0.0.1:7700\nprocesses:\n  - name: a\n    executable: x\n? - name: b\n  : 1\n";
  try {
    chatsim::launch::parse_launch_file(text, "odd.yaml");
    FAIL() << "expected LaunchFileError";
  } catch (const chatsim::launch::LaunchFileError& e) {
    EXPECT_NE(std::string(e.what()).find("odd.yaml:"), std::string::npos) << e.what();
  }
}
