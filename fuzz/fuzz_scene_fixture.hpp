#pragma once
// A small valid layout scene in a temporary folder, for the fuzz targets that need one.
#include <unistd.h>

#include <filesystem>
#include <string>

#include "common/scene/demo_layout.hpp"
#include "tests/support/scratch_dir.hpp"

namespace chatsim::fuzz {

inline std::string layout_scene_dir() {
  const auto dir = chatsim::scratch::dir() / ("chatsim-fuzz-scene-" + std::to_string(::getpid()));
  scene::DemoOptions o;
  o.frames = 20;
  scene::save_scene(scene::demo_layout(o), dir);
  return dir.string();
}

}  // namespace chatsim::fuzz
