#pragma once
// The models that draw assets: a catalogue entry (by asset name, else the generic entry of the
// vehicle's type) built as its parametric shape or loaded from its file, fitted to the size in
// the edit state and painted its colour. External files are loaded once and cached.
#include <array>
#include <string>

#include <Eigen/Core>

#include "render/asset_model.hpp"

namespace chatsim::agents::foreground {

struct AssetSpec {
  std::string asset;             // catalogue name, e.g. porsche_911 (unknown: use the type)
  std::string type = "car";
  Eigen::Vector3f size_lwh{4.5f, 1.85f, 1.45f};
  std::array<int, 3> color_rgb{128, 128, 128};
};

::chatsim::render::AssetModel model_for(const AssetSpec& spec);

// A file given directly (an asset preview): .glb/.gltf/.obj with glTF axis conventions.
::chatsim::render::AssetModel model_from_file(const std::string& file, const std::array<int, 3>& color_rgb);

}  // namespace chatsim::agents::foreground
