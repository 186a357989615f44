#pragma once
// A training configuration named in one word, as `chatsim bench nvs --configs` takes them:
// "<preset>[-<iterations>][-no-exposure][-no-pose-refinement][-dssim]", e.g. "fast-600-dssim".
#include <string>

#include "render/gs/trainer.hpp"

namespace chatsim::render::gs {

// The options the name asks for, over `base` (holdout, width, progress ...). Throws
// std::invalid_argument naming the config and what to write instead.
TrainOptions parse_train_config_name(const std::string& name, TrainOptions base = {});

}  // namespace chatsim::render::gs
