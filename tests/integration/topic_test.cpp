// chatsim topic list/echo against a real bus with a real agent on it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/bus_fixture.hpp"
#include "tests/support/subprocess.hpp"

using namespace chatsim;
using namespace std::chrono_literals;
using test_support::bin;
using test_support::ScopedProcess;

TEST(Topic, ListAndEchoShowHeartbeatsAsJson) {
  test_support::InProcessBus b;
  ScopedProcess agent(test_support::spawn({bin("chatsim-view"), "--bus", b.endpoint()}, "/dev/null"));
  const auto list_log = test_support::temp_path("topic-list.log");
  ScopedProcess list(test_support::spawn(
      {bin("chatsim"), "topic", "list", "--bus", b.endpoint(), "--duration-s", "1.5"}, list_log.string()));
  auto status = list.wait(10s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 0);
  const auto listed = test_support::read_file(list_log);
  EXPECT_NE(listed.find("/bus/heartbeat  [Heartbeat]"), std::string::npos) << listed;
  EXPECT_NE(listed.find("view"), std::string::npos) << listed;

  const auto echo_log = test_support::temp_path("topic-echo.log");
  ScopedProcess echo(test_support::spawn({bin("chatsim"), "topic", "echo", "/bus/heartbeat", "-n", "1", "--bus", b.endpoint()},
                                         echo_log.string()));
  status = echo.wait(10s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 0);
  const auto line = test_support::read_file(echo_log);
  const auto j = nlohmann::json::parse(line.substr(0, line.find('\n')));
  EXPECT_EQ(j["payload_type"], "Heartbeat");
  EXPECT_EQ(j["header"]["topic"], "/bus/heartbeat");
  EXPECT_FALSE(j["payload"]["node"].get<std::string>().empty());
}

TEST(Topic, NoBusIsExitCode3) {
  ScopedProcess p(test_support::spawn({bin("chatsim"), "topic", "list", "--bus", "tcp://127.0.0.1:1"}, "/dev/null"));
  const auto status = p.wait(10s);
  ASSERT_TRUE(status);
  EXPECT_EQ(WEXITSTATUS(*status), 3);
}
