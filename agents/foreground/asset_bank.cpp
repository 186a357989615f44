#include "agents/foreground/asset_bank.hpp"

#include <map>
#include <mutex>

#include "agents/asset/catalog.hpp"
#include "render/color.hpp"

namespace chatsim::agents::foreground {
namespace {

::chatsim::render::Rgb paint_of(const std::array<int, 3>& rgb) { return ::chatsim::render::linear_from_srgb8(rgb[0], rgb[1], rgb[2]); }

// Loading a file is the slow part; fitting and painting a copy is cheap.
::chatsim::render::AssetModel cached_external(const asset::ExternalModel& x) {
  static std::mutex mu;
  static std::map<std::string, ::chatsim::render::AssetModel> cache;
  const std::string key = x.file.string() + "|" + x.front_axis + "|" + x.up_axis + "|" + x.paint_material.value_or("");
  std::lock_guard lock(mu);
  auto it = cache.find(key);
  if (it == cache.end()) {
    ::chatsim::render::ExternalAssetOptions o;
    o.front_axis = x.front_axis;
    o.up_axis = x.up_axis;
    o.paint_material = x.paint_material;
    it = cache.emplace(key, ::chatsim::render::load_external_asset(x.file, o)).first;
  }
  return it->second;
}

}  // namespace

::chatsim::render::AssetModel model_for(const AssetSpec& spec) {
  const auto& catalog = asset::Catalog::instance();
  const asset::CatalogEntry* e = catalog.find(spec.asset);
  if (e == nullptr) e = &catalog.generic(spec.type);
  if (e->external) {
    ::chatsim::render::AssetModel m = cached_external(*e->external);
    m.fit_to(spec.size_lwh);
    m.recolour(paint_of(spec.color_rgb));
    return m;
  }
  return ::chatsim::render::build_parametric(e->shape, spec.size_lwh, paint_of(spec.color_rgb));
}

::chatsim::render::AssetModel model_from_file(const std::string& file, const std::array<int, 3>& color_rgb) {
  ::chatsim::render::AssetModel m = ::chatsim::render::load_external_asset(file);
  m.recolour(paint_of(color_rgb));
  return m;
}

}  // namespace chatsim::agents::foreground
