#pragma once
// Test helpers on lane layouts: a straight lane, and one conversation manager on one of the blind
// layouts (tests/data/layouts) with the offline backend: chat(id, command) gives the edit state
// after that round.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "agents/core/agent_registry.hpp"
#include "agents/llm/llm_backend.hpp"
#include "agents/manager/manager.hpp"
#include "common/scene/lane_map.hpp"

namespace chatsim::testing {

// A straight lane from (x0, y0) to (x1, y1), three centreline points.
inline scene::Lane straight_lane(const std::string& id, double x0, double y0, double x1, double y1) {
  scene::Lane l;
  l.id = id;
  l.centerline = {{x0, y0, 0}, {(x0 + x1) / 2, (y0 + y1) / 2, 0}, {x1, y1, 0}};
  return l;
}

// The ids an edit state removed, sorted.
inline std::vector<std::string> removed_ids(const nlohmann::json& state) {
  auto ids = state["removed"].get<std::vector<std::string>>();
  std::sort(ids.begin(), ids.end());
  return ids;
}

class LayoutChat {
 public:
  explicit LayoutChat(const std::string& layout)
      : dir_((std::filesystem::path(CHATSIM_SOURCE_DIR) / "tests/data/layouts" / layout).string()),
        backend_(agents::llm::make_backend("offline")),
        manager_(agents::local_caller(backend_), backend_) {}
  nlohmann::json operator()(const std::string& id, const std::string& command) {
    return manager_.chat(id, dir_, command).edit_state;
  }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::shared_ptr<agents::llm::Backend> backend_;
  agents::manager::Manager manager_;
};

}  // namespace chatsim::testing
