#pragma once
// How close a rendered result is to the demo scene's ground truth after vehicles were removed:
// each clean plate (the image without one vehicle, cropped to it and its shadow) against the
// same crop of the result, over the pixels the vehicle changed (where the plate differs from
// the captured image). Plates that overlap another removed vehicle's plate in the same image
// are left out: there the plate still shows that other vehicle.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::bench {

struct PlateAccuracy {
  int plates = 0;          // plates compared
  long pixels = 0;         // changed pixels compared
  double psnr_db = 0;      // over every compared pixel together (8-bit sRGB)
  double captured_psnr_db = 0;  // the captured image (vehicle still there) against the plates: the floor
};

// result_dir is a `chatsim run` result (frames/<camera>/<frame>.png); removed: the ids removed.
// Throws std::runtime_error naming the file when the scene has no plates or a frame is missing.
PlateAccuracy plate_accuracy(const scene::Scene& scene, const std::filesystem::path& result_dir,
                             const std::vector<std::string>& removed);

nlohmann::json to_json(const PlateAccuracy& a);

}  // namespace chatsim::bench
