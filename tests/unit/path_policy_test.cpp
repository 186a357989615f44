#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "common/util/path_policy.hpp"
#include "tests/support/scratch_dir.hpp"

using chatsim::PathPolicy;
namespace fs = std::filesystem;

TEST(PathPolicy, PathsMustStayInsideTheRoots) {
  const auto base = chatsim::scratch::dir() / ("chatsim-paths-" + std::to_string(::getpid()));
  fs::create_directories(base / "scenes" / "a");
  fs::create_directories(base / "secret");
  fs::remove(base / "scenes" / "link");
  fs::create_directory_symlink(base / "secret", base / "scenes" / "link");
  const PathPolicy policy({base / "scenes"});
  EXPECT_FALSE(policy.refuse("scene", base / "scenes" / "a"));
  EXPECT_FALSE(policy.refuse("scene", base / "scenes" / "not-yet-there"));
  const auto climbing = policy.refuse("scene", base / "scenes" / ".." / "secret");
  ASSERT_TRUE(climbing);
  EXPECT_NE(climbing->find("outside the allowed folders"), std::string::npos) << *climbing;
  EXPECT_TRUE(policy.refuse("scene", base / "scenes" / "link"));  // a symbolic link out is still out
  EXPECT_TRUE(policy.refuse("output", "/etc"));
  EXPECT_TRUE(policy.refuse("scene", base / "scenes-other"));     // a prefix of the name is not inside
  EXPECT_FALSE(PathPolicy().refuse("scene", "/anything"));        // no roots: a user's own machine
}

TEST(PathPolicy, RelativePathsStayInside) {
  EXPECT_TRUE(chatsim::stays_inside("images/front/000000.jpg"));
  EXPECT_TRUE(chatsim::stays_inside("images/../images/a.jpg"));
  EXPECT_FALSE(chatsim::stays_inside("../../etc/passwd"));
  EXPECT_FALSE(chatsim::stays_inside("images/../../x"));
  EXPECT_FALSE(chatsim::stays_inside("/etc/passwd"));
}
