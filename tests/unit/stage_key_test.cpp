// The cached deletion and foreground stages are reused only when what made them is the same:
// their keys carry what is removed or added, the input stage, and the versions of the fill and
// of the light estimator (whose sun shapes deletion's shadow masks and lights added vehicles).
#include <gtest/gtest.h>

#include "agents/render/render_cache.hpp"
#include "render/inpaint/deletion.hpp"
#include "render/light/light_estimate.hpp"

namespace chatsim::agents::render {
namespace {

TEST(StageKey, DeletionAndForegroundKeysCarryTheLightEstimatorsVersion) {
  const nlohmann::json bg{{"scene", "s"}};
  const nlohmann::json del = deletion_stage_key(bg, {"car_1"});
  EXPECT_EQ(del.at("light_version"), chatsim::render::light::kLightEstimatorVersion);
  EXPECT_EQ(del.at("fill_version"), chatsim::render::inpaint::kDeletionVersion);
  const nlohmann::json fg = foreground_stage_key(bg, {{{"id", "added_1"}}}, 32);
  EXPECT_EQ(fg.at("light_version"), chatsim::render::light::kLightEstimatorVersion);
  // What changes the output changes the key.
  EXPECT_NE(json_hash(del), json_hash(deletion_stage_key(bg, {"car_2"})));
  EXPECT_NE(json_hash(fg), json_hash(foreground_stage_key(bg, {{{"id", "added_1"}}}, 8)));
  EXPECT_NE(json_hash(fg), json_hash(foreground_stage_key(del, {{{"id", "added_1"}}}, 32)));
  EXPECT_EQ(json_hash(del), json_hash(deletion_stage_key(bg, {"car_1"}))) << "and the same inputs give the same key";
}

}  // namespace
}  // namespace chatsim::agents::render
