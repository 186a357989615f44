// The exit code a command's exception becomes (README: exit codes).
#include <gtest/gtest.h>

#include "processes/cli/command_errors.hpp"

namespace chatsim::cli {
namespace {

TEST(CommandErrors, NoBusIsBusUnavailable) {
  EXPECT_EQ(exit_code_of([]() -> int { throw bus::BusError("no bus"); }, [](const std::exception&) {}), exit_code::kBusUnavailable);
}

TEST(CommandErrors, InputTheUserCanFixIsUsage) {
  const auto quiet = [](const std::exception&) {};
  EXPECT_EQ(exit_code_of([]() -> int { throw scene::SceneError("scene.json", "frames", "missing"); }, quiet), exit_code::kUsage);
  EXPECT_EQ(exit_code_of([]() -> int { throw import::ImportError("no such scene"); }, quiet), exit_code::kUsage);
  EXPECT_EQ(exit_code_of([]() -> int { throw bag::McapError("truncated"); }, quiet), exit_code::kUsage);
  EXPECT_EQ(exit_code_of([]() -> int { throw std::invalid_argument("--width"); }, quiet), exit_code::kUsage);
  EXPECT_EQ(exit_code_of([]() -> int { throw OutputDirError("--out /home: not empty"); }, quiet), exit_code::kUsage);
}

TEST(CommandErrors, AnythingElseIsFailureAndIsReported) {
  std::string reported;
  EXPECT_EQ(exit_code_of([]() -> int { throw std::runtime_error("disk full"); }, [&](const std::exception& e) { reported = e.what(); }),
            exit_code::kFailure);
  EXPECT_EQ(reported, "disk full");
}

TEST(CommandErrors, TheBodysOwnCodePassesThrough) {
  bool reported = false;
  EXPECT_EQ(exit_code_of([] { return 7; }, [&](const std::exception&) { reported = true; }), 7);
  EXPECT_FALSE(reported);
}

}  // namespace
}  // namespace chatsim::cli
