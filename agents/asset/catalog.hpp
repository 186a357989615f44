#pragma once
// The asset catalogue: what assets exist (type, brand, real size, default paint) and which
// model draws each (a built-in parametric shape or a glTF/GLB/OBJ file). Read from
// assets/catalog.json, then from each folder in $CHATSIM_ASSETS (colon-separated): its
// catalog.json and every *.asset.json (one entry each); a later entry replaces an earlier one
// of the same name. Shared by the asset agent (choosing) and the foreground renderer (drawing).
#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace chatsim::agents::asset {

struct ExternalModel {
  std::filesystem::path file;     // absolute
  std::string front_axis = "+z";  // glTF convention
  std::string up_axis = "+y";
  std::optional<std::string> paint_material;
};

struct CatalogEntry {
  std::string asset;
  std::string type;
  std::string brand;              // "" for generic
  std::array<double, 3> size_lwh{};
  std::array<int, 3> color_rgb{};
  std::string shape;              // parametric shape, or "" when external
  std::optional<ExternalModel> external;
  std::filesystem::path defined_in;
};

class CatalogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Catalog {
 public:
  // The built-in catalogue plus $CHATSIM_ASSETS; loaded once. Throws CatalogError.
  static const Catalog& instance();
  // Entries from these files and folders in order (for tests and tools).
  static Catalog load(const std::vector<std::filesystem::path>& sources);

  const std::vector<CatalogEntry>& entries() const { return entries_; }
  const CatalogEntry* find(const std::string& asset) const;
  // The first generic (brand-less) entry of a type; a truck for a tractor or trailer (no mesh of
  // their own); the first entry when none.
  const CatalogEntry& generic(const std::string& type) const;

 private:
  void add_file(const std::filesystem::path& file);
  void add(CatalogEntry e);
  std::vector<CatalogEntry> entries_;
};

// Where the built-in catalogue lives ($CHATSIM_ASSETS_BUILTIN, else the source tree's assets/).
std::filesystem::path builtin_assets_dir();

}  // namespace chatsim::agents::asset
