// libFuzzer: any bytes as one of a scene's files (the first byte picks scene.json,
// objects.json or lanes.json; the others stay valid). Loading either succeeds or throws
// SceneError naming the file.
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "common/scene/scene.hpp"
#include "fuzz/fuzz_scene_fixture.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  if (size == 0) return 0;
  static const fs::path valid = chatsim::fuzz::layout_scene_dir();
  static const fs::path dir = fs::path(valid).concat("-mutated");
  static const char* files[] = {"scene.json", "objects.json", "lanes.json"};
  fs::create_directories(dir);
  for (const char* f : files) fs::copy_file(valid / f, dir / f, fs::copy_options::overwrite_existing);
  std::ofstream(dir / files[data[0] % 3], std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  try {
    chatsim::scene::load_scene(dir);
  } catch (const chatsim::scene::SceneError&) {
  }
  return 0;
}
