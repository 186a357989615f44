#include "agents/render/render_cache.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "render/inpaint/deletion.hpp"
#include "render/light/light_estimate.hpp"

namespace chatsim::agents::render {
namespace fs = std::filesystem;

fs::path cache_root() {
  if (const char* c = std::getenv("CHATSIM_CACHE"); c != nullptr && *c != '\0') return c;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x != nullptr && *x != '\0') return fs::path(x) / "chatsim";
  if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0') return fs::path(h) / ".cache" / "chatsim";
  return fs::temp_directory_path() / "chatsim-cache";
}

namespace {
uint64_t fnv1a(const std::string& s, uint64_t h = 1469598103934665603ULL) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}
std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}
std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

std::string scene_key(const scene::Scene& s) {
  uint64_t h = fnv1a(fs::absolute(s.dir).lexically_normal().string());
  for (const char* f : {"scene.json", "objects.json"})
    if (fs::exists(s.dir / f)) h = fnv1a(slurp(s.dir / f), h);
  std::string name = s.name.empty() ? "scene" : s.name;
  for (auto& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return name + "-" + hex(h);
}

fs::path scene_cache_dir(const scene::Scene& s) { return cache_root() / "scenes" / scene_key(s); }

std::string json_hash(const nlohmann::json& v) { return hex(fnv1a(v.dump())); }

nlohmann::json deletion_stage_key(const nlohmann::json& after, const nlohmann::json& removed) {
  return {{"after", after},
          {"removed", removed},
          {"fill_version", chatsim::render::inpaint::kDeletionVersion},
          {"light_version", chatsim::render::light::kLightEstimatorVersion}};
}

nlohmann::json foreground_stage_key(const nlohmann::json& after, const nlohmann::json& added, int spp) {
  return {{"after", after}, {"added", added}, {"spp", spp}, {"light_version", chatsim::render::light::kLightEstimatorVersion}};
}

bool stage_complete(const fs::path& dir) { return fs::exists(dir / "done.json"); }

void mark_stage_complete(const fs::path& dir, const nlohmann::json& info) {
  fs::create_directories(dir);
  const fs::path tmp = dir / ".done.json.part";
  std::ofstream(tmp) << info.dump(1) << "\n";
  fs::rename(tmp, dir / "done.json");
}

}  // namespace chatsim::agents::render
