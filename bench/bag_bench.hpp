#pragma once
// `chatsim bench bag`: can the recorder keep up with a camera stream? A node publishes
// 1920x1280 JPEG frames at 30 frames/s through the bus while the recorder writes them to MCAP;
// reports loss and the writer's throughput, against plain file writes of the same bytes
// measured in the same run.
#include <nlohmann/json.hpp>

namespace chatsim::bench {

struct BagBenchConfig {
  double seconds = 10;
  double fps = 30;
  int width = 1920, height = 1280;
};

nlohmann::json run_bag_bench(const BagBenchConfig& config);

}  // namespace chatsim::bench
