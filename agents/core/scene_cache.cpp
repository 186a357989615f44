#include "agents/core/scene_cache.hpp"

#include <map>
#include <mutex>

namespace chatsim::agents {
namespace fs = std::filesystem;

std::shared_ptr<const scene::Scene> cached_scene(const fs::path& dir) {
  struct Entry {
    fs::file_time_type stamp[3];
    std::shared_ptr<const scene::Scene> scene;
  };
  static std::mutex mu;
  static std::map<std::string, Entry> cache;
  auto stamp = [&](const char* name) {
    std::error_code ec;
    const auto t = fs::last_write_time(dir / name, ec);
    return ec ? fs::file_time_type{} : t;
  };
  const fs::file_time_type now[3] = {stamp("scene.json"), stamp("objects.json"), stamp("lanes.json")};
  const std::string key = fs::weakly_canonical(dir).string();
  std::lock_guard lock(mu);
  auto it = cache.find(key);
  if (it != cache.end() && std::equal(now, now + 3, it->second.stamp)) return it->second.scene;
  auto scene = std::make_shared<const scene::Scene>(scene::load_scene(dir));
  Entry e{{now[0], now[1], now[2]}, scene};
  cache[key] = e;
  return scene;
}

}  // namespace chatsim::agents
