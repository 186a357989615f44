#pragma once
// The names of the presets (draft, fast, quality), shared by every place that checks or offers
// them: the model's training, the rendering, the manager's request check and the CLI options.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace chatsim {

inline const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> names{"draft", "fast", "quality"};
  return names;
}

inline bool is_preset_name(std::string_view name) {
  const auto& n = preset_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

// For error messages: "use draft, fast or quality".
inline constexpr std::string_view kPresetChoices = "draft, fast or quality";

}  // namespace chatsim
