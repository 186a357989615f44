#include "common/util/path_policy.hpp"

namespace chatsim {
namespace fs = std::filesystem;

PathPolicy::PathPolicy(const std::vector<fs::path>& roots) {
  for (const auto& r : roots) roots_.push_back(fs::weakly_canonical(fs::absolute(r)));
}

std::optional<std::string> PathPolicy::refuse(const std::string& what, const fs::path& path) const {
  if (roots_.empty() || path.empty()) return std::nullopt;
  const fs::path p = fs::weakly_canonical(fs::absolute(path));  // resolves "..", and symbolic links that exist
  for (const auto& root : roots_) {
    const auto rel = p.lexically_relative(root);
    if (!rel.empty() && stays_inside(rel)) return std::nullopt;
  }
  std::string allowed;
  for (const auto& r : roots_) allowed += (allowed.empty() ? "" : ", ") + r.string();
  return what + " path '" + path.string() + "' is outside the allowed folders (" + allowed + ")";
}

bool stays_inside(const fs::path& relative) {
  if (relative.is_absolute() || relative.has_root_path()) return false;
  const auto n = relative.lexically_normal();
  return n.empty() || *n.begin() != "..";
}

}  // namespace chatsim
