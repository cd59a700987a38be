// Edge detection (Nienhaus & Döllner 2003, as given in Pacheco §2): parity of the GPU pass and the reference on the
// same G-buffer, in both normal modes, plus the formula's own properties.
#include <gtest/gtest.h>

#include "parity/parity.hpp"
#include "reference/pencil/edge_detect.hpp"
#include "reference/scene/gbuffer.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

using testing::GlTest;

class EdgeDetectParity : public GlTest, public ::testing::WithParamInterface<std::tuple<std::string, std::string>> {};

// Both backends evaluate the same float expression on the same float inputs; the only
// difference is the GPU's instruction selection (fused multiply-add). Measured max abs
// on llvmpipe: ~1e-7. Tolerance 1e-4 (docs/conventions.md float target, 1e-3) leaves no pixel over.
TEST_P(EdgeDetectParity, GpuMatchesReferenceOnTheSameGBuffer) {
  auto [scene_name, mode] = GetParam();
  Scene scene = testing::builtin_at(scene_name, 320, 240);
  scene.params.set("edge.normals", mode);
  auto results = run_parity(scene, {"edge_detect"});
  ASSERT_EQ(testing::names_of(results), testing::kEdgeAndLightResults);
  const StageParity& r = results[0];
  std::printf("[edge_detect %s %s] %s\n", scene_name.c_str(), mode.c_str(), format_diff(r.name, r.diff).c_str());
  EXPECT_TRUE(r.pass);
  EXPECT_EQ(r.diff.over_tolerance, 0.0);
  EXPECT_FALSE(has_non_finite(r.gpu));
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, EdgeDetectParity,
                         ::testing::Combine(::testing::Values("torus", "sphere", "cad"),
                                            ::testing::Values("interpolated", "face")));

TEST_F(GlTest, EdgeDetectParityOnFandiskBothModes) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  for (const char* mode : {"interpolated", "face"}) {
    Scene scene = testing::model_scene("fandisk.obj", 800, 800);
    scene.params.set("edge.normals", mode);
    auto r = run_parity(scene, {"edge_detect"}).at(0);
    std::printf("[edge_detect fandisk %s] %s\n", mode, format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << mode;
  }
}

// The formula itself, on hand-made G-buffers.
GBuffer flat_gbuffer(int w, int h, float depth) {
  GBuffer g;
  g.normal = Image(w, h, 3);
  for (size_t i = 0; i < g.normal.pixels(); ++i) g.normal.data[i * 3 + 2] = 1.0f;
  g.face_normal = g.normal;
  g.depth = Image(w, h, 1, depth);
  g.ids = ImageU32(w, h, 2, 1);
  g.bary = Image(w, h, 3);
  g.gouraud = Image(w, h, 1, 1.0f);
  g.near = 1;
  g.far = 11;
  return g;
}

TEST(EdgeDetectReference, FlatPlaneHasNoContour) {
  GBuffer g = flat_gbuffer(8, 8, 5.0f);
  Image d = reference::contour_darkness(g, ParamSet{}.get<EdgeDetectParams>());
  for (float v : d.data) EXPECT_FLOAT_EQ(v, 0.0f);
}

TEST(EdgeDetectReference, DepthStepDarkensOnlyItsNeighborsByTheFormula) {
  GBuffer g = flat_gbuffer(8, 8, 5.0f);
  for (int y = 0; y < 8; ++y)
    for (int x = 4; x < 8; ++x) g.depth.at(x, y) = 6.0f;  // z jumps by 0.1
  ParamSet set;
  set.set("edge.depth_scale", 4.0);  // factor (1 - min(1, 2 * 0.1))^2 = 0.64 per diagonal
  Image d = reference::contour_darkness(g, set.get<EdgeDetectParams>());
  EXPECT_NEAR(d.at(3, 4), 1.0f - 0.64f * 0.64f, 1e-5);  // both diagonals straddle the step
  EXPECT_NEAR(d.at(4, 4), 1.0f - 0.64f * 0.64f, 1e-5);
  EXPECT_FLOAT_EQ(d.at(1, 4), 0.0f);
  EXPECT_FLOAT_EQ(d.at(6, 4), 0.0f);
}

TEST(EdgeDetectReference, OppositeNormalsGiveFullDarkness) {
  GBuffer g = flat_gbuffer(8, 8, 5.0f);
  for (int y = 0; y < 8; ++y)
    for (int x = 4; x < 8; ++x) g.normal.at(x, y, 2) = -1.0f;
  Image d = reference::contour_darkness(g, ParamSet{}.get<EdgeDetectParams>());
  EXPECT_FLOAT_EQ(d.at(3, 4), 1.0f);  // I_n = clamp(-1) = 0
  EXPECT_FLOAT_EQ(d.at(0, 4), 0.0f);
}

}  // namespace
}  // namespace plumbago
