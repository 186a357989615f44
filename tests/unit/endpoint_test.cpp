#include <gtest/gtest.h>

#include "common/bus/endpoint.hpp"

using chatsim::bus::split_bus_endpoint;

TEST(Endpoint, TcpUsesPortAndNextPort) {
  const auto ep = split_bus_endpoint("tcp://127.0.0.1:7700");
  EXPECT_EQ(ep.publish, "tcp://127.0.0.1:7700");
  EXPECT_EQ(ep.subscribe, "tcp://127.0.0.1:7701");
}

TEST(Endpoint, IpcAndInprocGetSuffixes) {
  EXPECT_EQ(split_bus_endpoint("ipc:///tmp/b").publish, "ipc:///tmp/b.pub");
  EXPECT_EQ(split_bus_endpoint("inproc://x").subscribe, "inproc://x.sub");
}

TEST(Endpoint, BadInputNamesTheEndpointAndTheProblem) {
  for (const char* bad : {"127.0.0.1:7700", "udp://h:1", "tcp://h", "tcp://h:abc", "tcp://h:70000", "tcp://h:0"}) {
    try {
      split_bus_endpoint(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}
