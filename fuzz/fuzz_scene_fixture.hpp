#pragma once
// A small valid layout scene in a temporary folder, for the fuzz targets that need one.
#include <unistd.h>

#include <filesystem>
#include <string>

#include "common/scene/demo_layout.hpp"

namespace chatsim::fuzz {

inline std::string layout_scene_dir() {
  const auto dir = std::filesystem::temp_directory_path() / ("chatsim-fuzz-scene-" + std::to_string(::getpid()));
  scene::DemoOptions o;
  o.frames = 20;
  scene::save_scene(scene::demo_layout(o), dir);
  return dir.string();
}

}  // namespace chatsim::fuzz
