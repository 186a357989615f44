#include "render/gs/train_config_name.hpp"

#include <stdexcept>

#include "common/util/preset_names.hpp"

namespace chatsim::render::gs {

TrainOptions parse_train_config_name(const std::string& name, TrainOptions o) {
  const auto fail = [&](const std::string& why) {
    return std::invalid_argument("config '" + name + "': " + why +
                                 " (write <preset>[-<iterations>][-no-exposure][-no-pose-refinement][-dssim][-coarse], e.g. fast-600-dssim)");
  };
  std::string rest = name;
  // Switches come off the end, each once, in any order.
  const auto take = [&](const std::string& suffix) {
    if (rest.size() <= suffix.size() || rest.compare(rest.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
    rest.erase(rest.size() - suffix.size());
    return true;
  };
  bool no_exposure = false, no_pose = false, dssim = false, coarse = false;
  for (bool found = true; found;) {
    found = false;
    if (!no_exposure && take("-no-exposure")) no_exposure = found = true;
    if (!no_pose && take("-no-pose-refinement")) no_pose = found = true;
    if (!dssim && take("-dssim")) dssim = found = true;
    if (!coarse && take("-coarse")) coarse = found = true;
  }
  const size_t dash = rest.find('-');
  const std::string preset = rest.substr(0, dash);
  if (!is_preset_name(preset)) throw fail("unknown preset '" + preset + "', use " + std::string(kPresetChoices));
  o.preset = preset;
  if (dash != std::string::npos) {
    const std::string count = rest.substr(dash + 1);
    const bool digits = !count.empty() && count.size() <= 7 && count.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || std::stoi(count) < 1) throw fail("'" + count + "' is neither an iteration count (1-9999999) nor a switch");
    o.max_iterations = std::stoi(count);
  }
  o.exposure = !no_exposure;
  o.pose_refinement = !no_pose;
  if (dssim) o.ssim_weight = 0.2f;
  if (coarse) o.coarse_share = kCoarseConfigShare;
  return o;
}

}  // namespace chatsim::render::gs
