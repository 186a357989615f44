// The asset bank: parametric vehicles at exact sizes with their material slots, external
// glTF/OBJ files normalised (metres, origin, heading, paint), and the catalogue's checks.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "agents/asset/catalog.hpp"
#include "agents/foreground/asset_bank.hpp"
#include "render/asset_model.hpp"
#include "tests/support/scratch_dir.hpp"

namespace chatsim {
namespace {
namespace fs = std::filesystem;

const fs::path kKenney = fs::path(CHATSIM_SOURCE_DIR) / ".." / "shared" / "data" / "kenney-glb";

TEST(AssetBank, EveryParametricShapeFillsItsBoxExactly) {
  for (const auto& shape : render::parametric_shapes()) {
    const Eigen::Vector3f size(4.2f, 1.8f, 1.5f);
    const auto m = render::build_parametric(shape, size, render::Rgb(0.5f, 0.1f, 0.1f));
    const auto b = m.mesh.bounds();
    EXPECT_LT((b.sizes() - size).cwiseAbs().maxCoeff(), 1e-3f) << shape;
    EXPECT_NEAR(b.min().z(), 0.0f, 1e-4f) << shape;                 // origin at the bottom ...
    EXPECT_NEAR(b.center().x(), 0.0f, 1e-4f) << shape;              // ... centre
    EXPECT_NEAR(b.center().y(), 0.0f, 1e-4f) << shape;
    EXPECT_GT(m.mesh.triangle_count(), 10u) << shape;
    for (uint16_t s : m.mesh.material) ASSERT_LT(s, m.slots.size()) << shape;
  }
  EXPECT_THROW(render::build_parametric("spaceship", {4, 2, 1.5f}, render::Rgb::Ones()), std::invalid_argument);
}

TEST(AssetBank, CarsHaveTheirMaterialsAndHeadlightsAtTheFront) {
  const auto m = render::build_parametric("sedan", {4.6f, 1.85f, 1.45f}, render::Rgb(0.6f, 0.02f, 0.02f));
  std::set<std::string> names;
  for (const auto& s : m.slots) names.insert(s.name);
  for (const char* n : {"paint", "glass", "tyre", "chrome", "headlight", "taillight"}) EXPECT_TRUE(names.count(n)) << n;
  // Headlight triangles sit at the front (+x), taillights at the back.
  double head_x = 0, tail_x = 0;
  int nh = 0, nt = 0;
  for (size_t t = 0; t < m.mesh.triangles.size(); ++t) {
    const auto& name = m.slots[m.mesh.material[t]].name;
    const float x = m.mesh.positions[size_t(m.mesh.triangles[t][0])].x();
    if (name == "headlight") head_x += x, ++nh;
    if (name == "taillight") tail_x += x, ++nt;
  }
  EXPECT_GT(head_x / nh, 2.0);
  EXPECT_LT(tail_x / nt, -2.0);
}

TEST(AssetBank, RecolouringChangesOnlyThePaint) {
  auto m = render::build_parametric("suv", {4.8f, 1.95f, 1.75f}, render::Rgb(0.5f, 0.5f, 0.5f));
  const auto before = m.slots;
  m.recolour(render::Rgb(0.0f, 0.0f, 0.8f));
  for (size_t s = 0; s < m.slots.size(); ++s) {
    if (int(s) == m.paint_slot) EXPECT_FLOAT_EQ(m.slots[s].albedo.z(), 0.8f);
    else EXPECT_EQ(m.slots[s].albedo, before[s].albedo);
  }
}

TEST(AssetBank, KenneyGlbIsNormalisedToOurConvention) {
  const fs::path file = kKenney / "sedan.glb";
  if (!fs::exists(file)) GTEST_SKIP() << "no " << file << " (../shared/data is not here)";
  const auto m = render::load_external_asset(file);
  const auto b = m.mesh.bounds();
  // y-up, +z-forward glTF became z-up, +x-forward: longest along x, origin at the bottom centre.
  EXPECT_GT(b.sizes().x(), 1.4f * b.sizes().y());
  EXPECT_NEAR(b.min().z(), 0.0f, 1e-4f);
  EXPECT_NEAR(b.center().x(), 0.0f, 1e-3f);
  EXPECT_NEAR(b.sizes().x(), 2.55f, 0.1f);  // Kenney's models are about half real size
  // The paint covers much of the body; the yellow headlights are at the front.
  ASSERT_GE(m.paint_slot, 0);
  float paint = 0, all = 0;
  double yellow_x = 0;
  int yellow = 0;
  for (size_t t = 0; t < m.mesh.triangles.size(); ++t) {
    const auto& p = m.mesh.positions;
    const auto& tri = m.mesh.triangles[t];
    const float a = 0.5f * (p[size_t(tri[1])] - p[size_t(tri[0])]).cross(p[size_t(tri[2])] - p[size_t(tri[0])]).norm();
    all += a;
    if (m.mesh.material[t] == m.paint_slot) paint += a;
    const auto& c = m.slots[m.mesh.material[t]].albedo;
    if (c.x() > 0.5f && c.y() > 0.3f && c.z() < 0.1f) yellow_x += p[size_t(tri[0])].x(), ++yellow;
  }
  EXPECT_GT(paint / all, 0.25f);
  ASSERT_GT(yellow, 0);
  EXPECT_GT(yellow_x / yellow, 0.5);
  // Fitted to a real size through the catalogue's path.
  auto fitted = m;
  fitted.fit_to({4.6f, 1.85f, 1.45f});
  EXPECT_LT((fitted.mesh.bounds().sizes() - Eigen::Vector3f(4.6f, 1.85f, 1.45f)).norm(), 1e-3f);
}

TEST(AssetBank, ObjWithMaterialsLoadsAndNamedPaintIsUsed) {
  const fs::path dir = chatsim::scratch::dir() / ("chatsim-obj-" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "box.mtl") << "newmtl body\nKd 0.8 0.1 0.1\nnewmtl tyre\nKd 0.02 0.02 0.02\n";
  // A 4 x 2 x 1 box, y up, front toward +z as in glTF, with one "tyre" face.
  std::ofstream(dir / "box.obj") << "mtllib box.mtl\n"
                                    "v -1 0 -2\nv 1 0 -2\nv 1 1 -2\nv -1 1 -2\nv -1 0 2\nv 1 0 2\nv 1 1 2\nv -1 1 2\n"
                                    "usemtl body\nf 1 2 3 4\nf 5 6 7 8\nf 4 3 7 8\nf 1 4 8 5\nf 2 6 7 3\nusemtl tyre\nf 1 5 6 2\n";
  render::ExternalAssetOptions o;
  o.paint_material = "body";
  const auto m = render::load_external_asset(dir / "box.obj", o);
  EXPECT_NEAR(m.size().x(), 4.0f, 1e-4f);
  EXPECT_NEAR(m.size().y(), 2.0f, 1e-4f);
  EXPECT_NEAR(m.size().z(), 1.0f, 1e-4f);
  ASSERT_GE(m.paint_slot, 0);
  EXPECT_NEAR(m.slots[size_t(m.paint_slot)].albedo.x(), 0.8f, 1e-4f);
  o.paint_material = "nothing";
  try {
    render::load_external_asset(dir / "box.obj", o);
    FAIL() << "a missing paint material must be refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("box.obj"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("nothing"), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(AssetBank, BadFilesAreRefusedNamingTheFile) {
  const fs::path dir = chatsim::scratch::dir() / ("chatsim-badasset-" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "broken.glb") << "this is not a glb";
  for (const fs::path& f : {dir / "broken.glb", dir / "missing.obj", dir / "model.fbx"}) {
    try {
      render::load_external_asset(f);
      ADD_FAILURE() << f << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(f.filename().string()), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}

TEST(AssetCatalog, EntriesAreCheckedAndOverlaysReplaceByName) {
  const fs::path dir = chatsim::scratch::dir() / ("chatsim-catalog-" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "mine.asset.json") << R"({"asset": "sedan", "type": "car", "size_lwh": [4.0, 1.8, 1.4],
      "color_rgb": [1, 2, 3], "model": {"file": "car.glb"}})";
  const auto c = agents::asset::Catalog::load({agents::asset::builtin_assets_dir() / "catalog.json", dir});
  const auto* e = c.find("sedan");
  ASSERT_NE(e, nullptr);
  ASSERT_TRUE(e->external.has_value());
  EXPECT_EQ(e->external->file, (dir / "car.glb").lexically_normal());
  EXPECT_EQ(e->color_rgb[2], 3);
  std::ofstream(dir / "bad.asset.json") << R"({"asset": "x", "type": "car", "size_lwh": [4.0, -1, 1.4],
      "color_rgb": [1, 2, 3], "model": "sedan"})";
  try {
    agents::asset::Catalog::load({dir});
    FAIL() << "a negative size must be refused";
  } catch (const agents::asset::CatalogError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.asset.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("size_lwh[1]"), std::string::npos);
  }
  fs::remove_all(dir);
}

TEST(AssetCatalog, EveryBuiltInEntryBuilds) {
  for (const auto& e : agents::asset::Catalog::instance().entries()) {
    const Eigen::Vector3f size(float(e.size_lwh[0]), float(e.size_lwh[1]), float(e.size_lwh[2]));
    const auto m = agents::foreground::model_for({e.asset, e.type, size, e.color_rgb});
    EXPECT_LT((m.mesh.bounds().sizes() - size).norm(), 1e-3f) << e.asset;
  }
  // An asset name the catalogue does not know draws as its type's generic model.
  const auto m = agents::foreground::model_for({"porsche_suv", "suv", {4.8f, 1.95f, 1.75f}, {1, 2, 3}});
  EXPECT_GT(m.mesh.triangle_count(), 100u);
}

}  // namespace
}  // namespace chatsim
