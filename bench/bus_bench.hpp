#pragma once
// `chatsim bench bus`: the bus against raw ZeroMQ PUB/SUB, same sizes, same transport,
// measured in one run so the ratios mean something on any machine.
#include <string>

#include <nlohmann/json.hpp>

namespace chatsim::bench {

struct BusBenchConfig {
  std::string host = "127.0.0.1";
  int small_size = 1024;           // bytes
  int small_count = 200000;
  int image_size = 6 * 1024 * 1024;
  int image_count = 300;
  int latency_count = 5000;
  int repeats = 5;                 // median of N per measurement, against scheduling noise
};

// Runs every measurement and returns the report (see bench/README.md for its fields).
nlohmann::json run_bus_bench(const BusBenchConfig& config);

}  // namespace chatsim::bench
