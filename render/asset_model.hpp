#pragma once
// A 3D asset ready to render: one merged mesh in metres, origin at the bottom centre, facing +x,
// z up, with named material slots of which one is the paint (recolouring changes only it).
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/material.hpp"
#include "render/mesh.hpp"

namespace chatsim::render {

struct AssetModel {
  std::string name;
  TriangleMesh mesh;
  std::vector<Material> slots;
  int paint_slot = 0;          // -1: nothing to recolour (cones, barriers)

  Eigen::Vector3f size() const { return mesh.bounds().sizes(); }  // length (x), width (y), height (z)
  void recolour(const Rgb& linear_albedo);
  // Scales each axis so the bounding box is exactly size_lwh, then puts the origin at the
  // bottom centre.
  void fit_to(const Eigen::Vector3f& size_lwh);
};

// The parametric shapes built in: sedan, sports, hatchback, suv, pickup, van, bus, box_truck,
// police, taxi, ambulance, firetruck, motorcycle, bicycle, cone, barrier.
const std::vector<std::string>& parametric_shapes();
bool is_parametric_shape(const std::string& shape);
// Builds a parametric shape at size_lwh with the given paint (linear albedo). Throws
// std::invalid_argument naming the shapes there are when `shape` is unknown.
AssetModel build_parametric(const std::string& shape, const Eigen::Vector3f& size_lwh, const Rgb& paint);

// How an external file is oriented and which of its materials is the paint.
struct ExternalAssetOptions {
  std::string front_axis = "+z";               // glTF's convention: the front faces +z
  std::string up_axis = "+y";                  // glTF: +y up
  std::optional<Eigen::Vector3f> size_lwh;     // real size; else the file's units are metres
  std::optional<std::string> paint_material;   // a material name; else found by colour
};

// Loads a glTF (.gltf/.glb) or OBJ file and normalises it (metres, origin at the bottom centre,
// facing +x, z up, meshes merged, the body's material as the paint slot). Per-triangle colours
// come from base colour textures sampled at each triangle's centre, so palette-textured
// low-poly models keep their colours. Throws std::runtime_error naming the file and problem.
AssetModel load_external_asset(const std::filesystem::path& file, const ExternalAssetOptions& options = {});

}  // namespace chatsim::render
