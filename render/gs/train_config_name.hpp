#pragma once
// A training configuration named in one word, as `chatsim bench nvs --configs` takes them:
// "<preset>[-<iterations>][-no-exposure][-no-pose-refinement][-dssim][-coarse]", e.g.
// "fast-600-dssim".
#include <string>

#include "render/gs/trainer.hpp"

namespace chatsim::render::gs {

// `-coarse`: this share of the iterations at half resolution, not TrainOptions' 0.3 (on
// nuScenes, 1500 iterations so took 312 s for 19.05 dB held out, with 0.3 439 s for 19.06).
inline constexpr float kCoarseConfigShare = 0.8f;

// The options the name asks for, over `base` (holdout, width, progress ...). Throws
// std::invalid_argument naming the config and what to write instead.
TrainOptions parse_train_config_name(const std::string& name, TrainOptions base = {});

}  // namespace chatsim::render::gs
