#pragma once
// Foreground rendering speed against noise: one car covering about a fifth of a 640 x 426
// frame, path traced over the area it and its shadow cover at several sample counts, with and
// without the smoothing of diffuse light; noise is the PSNR against a 1024-sample render.
#include <nlohmann/json.hpp>

namespace chatsim::bench {

struct ForegroundBenchConfig {
  std::vector<int> spp{4, 8, 16, 32, 64};
  int reference_spp = 1024;
  bool quick = false;  // smaller reference (256 samples)
};

nlohmann::json run_foreground_bench(const ForegroundBenchConfig& config);

}  // namespace chatsim::bench
