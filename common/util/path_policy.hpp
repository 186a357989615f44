#pragma once
// Which folders paths from messages and commands may name. With roots configured, a path
// (after resolving "..", symbolic links and relative parts) must lie inside one of them.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace chatsim {

class PathPolicy {
 public:
  PathPolicy() = default;  // no roots: every path is allowed (a user's own machine)
  explicit PathPolicy(const std::vector<std::filesystem::path>& roots);

  bool restricted() const { return !roots_.empty(); }
  // Why `path` (named by `what`, e.g. "scene") is not allowed, or nothing when it is.
  std::optional<std::string> refuse(const std::string& what, const std::filesystem::path& path) const;

 private:
  std::vector<std::filesystem::path> roots_;  // canonical
};

// True when `relative` stays inside its base folder (no absolute path, no climbing out with "..").
bool stays_inside(const std::filesystem::path& relative);

}  // namespace chatsim
