#pragma once
// Grades an edit state against the checks of a command case (format:
// ../shared/data/commands/README.md). Geometry is read in the ego frame at frame 0.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/scene/scene.hpp"

namespace chatsim::bench {

struct CheckResult {
  bool pass = false;
  std::string check;    // the check as JSON text
  std::string detail;   // why it failed
};

std::vector<CheckResult> grade_case(const scene::Scene& scene, const nlohmann::json& edit_state,
                                    const nlohmann::json& expect);

// Motion quality of every added vehicle: does it stay on lanes, does what it does match its
// resolved intent (action and speed), and does it keep clear of every other vehicle?
struct MotionQuality {
  int vehicles = 0;
  int on_lane = 0;
  int action_match = 0;
  int speed_match = 0;
  int no_overlap = 0;   // meets no other vehicle (labelled and kept, or added) at any frame
  int clear_of_ego = 0; // never where the recording car is (its recorded path cannot give way)
};
MotionQuality motion_quality(const scene::Scene& scene, const nlohmann::json& edit_state);

}  // namespace chatsim::bench
