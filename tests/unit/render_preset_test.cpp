// The rendering presets a user picks: each names a radiance field preset the trainer knows and
// more samples per pixel the higher it goes; unknown names are refused with the choices.
#include <gtest/gtest.h>

#include "agents/render/render_pipeline.hpp"

namespace chatsim::agents::render {
namespace {

TEST(RenderPreset, DraftFastQualityGrowAndFastIsTheDefault) {
  EXPECT_EQ(render_preset("").model, "fast");
  EXPECT_EQ(render_preset("").foreground_spp, render_preset("fast").foreground_spp);
  EXPECT_LT(render_preset("draft").foreground_spp, render_preset("fast").foreground_spp);
  EXPECT_LT(render_preset("fast").foreground_spp, render_preset("quality").foreground_spp);
  EXPECT_EQ(render_preset("draft").model, "draft");
  EXPECT_EQ(render_preset("quality").model, "quality");
  try {
    render_preset("ultra");
    FAIL() << "an unknown preset was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("use draft, fast or quality"), std::string::npos);
  }
}

}  // namespace
}  // namespace chatsim::agents::render
