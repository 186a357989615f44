#include "agents/asset/catalog.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace chatsim::agents::asset {
namespace fs = std::filesystem;
using nlohmann::json;

fs::path builtin_assets_dir() {
  if (const char* env = std::getenv("CHATSIM_ASSETS_BUILTIN"); env != nullptr && *env != '\0') return env;
  return CHATSIM_ASSETS_DIR;
}

namespace {

[[noreturn]] void fail(const fs::path& file, const std::string& field, const std::string& what) {
  throw CatalogError(file.string() + ": " + field + ": " + what);
}

CatalogEntry parse_entry(const json& j, const fs::path& file, const std::string& where) {
  if (!j.is_object()) fail(file, where, "must be an object");
  CatalogEntry e;
  e.defined_in = file;
  auto str = [&](const char* key, bool required) -> std::string {
    if (!j.contains(key)) {
      if (required) fail(file, where + "." + key, "missing (add it)");
      return "";
    }
    if (!j[key].is_string()) fail(file, where + "." + key, "must be a string");
    return j[key].get<std::string>();
  };
  e.asset = str("asset", true);
  e.type = str("type", true);
  e.brand = str("brand", false);
  if (!j.contains("size_lwh") || !j["size_lwh"].is_array() || j["size_lwh"].size() != 3)
    fail(file, where + ".size_lwh", "must be [length, width, height] in metres");
  for (size_t k = 0; k < 3; ++k) {
    if (!j["size_lwh"][k].is_number() || !(j["size_lwh"][k].get<double>() > 0.05) || j["size_lwh"][k].get<double>() > 30)
      fail(file, where + ".size_lwh[" + std::to_string(k) + "]", "must be a size in metres between 0.05 and 30");
    e.size_lwh[k] = j["size_lwh"][k].get<double>();
  }
  if (!j.contains("color_rgb") || !j["color_rgb"].is_array() || j["color_rgb"].size() != 3)
    fail(file, where + ".color_rgb", "must be [r, g, b] with 0..255 each");
  for (size_t k = 0; k < 3; ++k) {
    if (!j["color_rgb"][k].is_number_integer() || j["color_rgb"][k].get<int>() < 0 || j["color_rgb"][k].get<int>() > 255)
      fail(file, where + ".color_rgb[" + std::to_string(k) + "]", "must be an integer 0..255");
    e.color_rgb[k] = j["color_rgb"][k].get<int>();
  }
  if (!j.contains("model")) fail(file, where + ".model", "missing: a parametric shape name or {\"file\": ...}");
  const json& m = j["model"];
  if (m.is_string()) {
    e.shape = m.get<std::string>();
  } else if (m.is_object()) {
    if (!m.contains("file") || !m["file"].is_string()) fail(file, where + ".model.file", "missing: the glTF/GLB/OBJ file");
    ExternalModel x;
    x.file = m["file"].get<std::string>();
    if (x.file.is_relative()) x.file = fs::absolute(file.parent_path() / x.file).lexically_normal();
    if (m.contains("front_axis")) x.front_axis = m["front_axis"].get<std::string>();
    if (m.contains("up_axis")) x.up_axis = m["up_axis"].get<std::string>();
    if (m.contains("paint_material")) x.paint_material = m["paint_material"].get<std::string>();
    e.external = x;
  } else {
    fail(file, where + ".model", "must be a parametric shape name or {\"file\": ...}");
  }
  return e;
}

json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw CatalogError(file.string() + ": cannot be read");
  try {
    return json::parse(in);
  } catch (const json::parse_error& e) {
    throw CatalogError(file.string() + ": not valid JSON: " + e.what());
  }
}

}  // namespace

void Catalog::add(CatalogEntry e) {
  for (auto& old : entries_)
    if (old.asset == e.asset) {
      old = std::move(e);
      return;
    }
  entries_.push_back(std::move(e));
}

void Catalog::add_file(const fs::path& file) {
  const json j = read_json(file);
  if (j.contains("assets")) {
    if (!j["assets"].is_array()) fail(file, "assets", "must be a list of entries");
    for (size_t i = 0; i < j["assets"].size(); ++i) add(parse_entry(j["assets"][i], file, "assets[" + std::to_string(i) + "]"));
  } else {
    add(parse_entry(j, file, "(entry)"));
  }
}

Catalog Catalog::load(const std::vector<fs::path>& sources) {
  Catalog c;
  for (const auto& src : sources) {
    if (fs::is_directory(src)) {
      if (fs::exists(src / "catalog.json")) c.add_file(src / "catalog.json");
      std::vector<fs::path> extra;
      for (const auto& f : fs::directory_iterator(src)) {
        const std::string name = f.path().filename().string();
        if (name.size() > 11 && name.compare(name.size() - 11, 11, ".asset.json") == 0) extra.push_back(f.path());
      }
      std::sort(extra.begin(), extra.end());
      for (const auto& f : extra) c.add_file(f);
    } else if (fs::exists(src)) {
      c.add_file(src);
    } else {
      throw CatalogError(src.string() + ": no such asset file or folder (check $CHATSIM_ASSETS)");
    }
  }
  if (c.entries_.empty()) throw CatalogError("no assets found in the catalogue (looked in " + builtin_assets_dir().string() + ")");
  return c;
}

const Catalog& Catalog::instance() {
  static const Catalog c = [] {
    std::vector<fs::path> sources{builtin_assets_dir() / "catalog.json"};
    if (const char* env = std::getenv("CHATSIM_ASSETS"); env != nullptr) {
      std::stringstream ss(env);
      for (std::string part; std::getline(ss, part, ':');)
        if (!part.empty()) sources.emplace_back(part);
    }
    return load(sources);
  }();
  return c;
}

const CatalogEntry* Catalog::find(const std::string& asset) const {
  for (const auto& e : entries_)
    if (e.asset == asset) return &e;
  return nullptr;
}

const CatalogEntry& Catalog::generic(const std::string& type) const {
  for (const auto& e : entries_)
    if (e.brand.empty() && e.type == type) return e;
  // A kind with no mesh of its own (a tractor, a trailer): the nearest in build, a truck.
  if (type == "construction" || type == "trailer") return generic("truck");
  return entries_.front();
}

}  // namespace chatsim::agents::asset
