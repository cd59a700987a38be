// Interior pencil shading (SPEC 2.6-2.10): GPU vs reference on the same inputs, the
// effect switches, and the composition with interior and paper.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/parity.hpp"
#include "common/lights.hpp"
#include "common/preprocess.hpp"
#include "reference/gbuffer.hpp"
#include "reference/interior_intensity.hpp"
#include "reference/pencil_interior.hpp"
#include "tests/test_scenes.hpp"

namespace plumbago {
namespace {

class PencilInteriorParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

// Bilinear/trilinear lookups of the pencil stack at rotated coordinates; measured max
// abs 7e-6 on llvmpipe (float textures are filtered with float weights).
TEST_P(PencilInteriorParity, GpuMatchesReference) {
  Scene scene = testing::builtin_at(GetParam(), 320, 240);
  for (const StageParity& r : run_parity(scene, {"pencil_interior", "compose"})) {
    std::printf("[%s %s] %s\n", r.name.c_str(), GetParam().c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PencilInteriorParity, ::testing::Values("torus", "sphere", "cad"));

TEST_F(PencilInteriorParity, Fandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  for (const StageParity& r : run_parity(testing::model_scene("fandisk.obj", 400, 400), {"pencil_interior"})) {
    std::printf("[%s fandisk] %s\n", r.name.c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name;
  }
}

// "interior" without "crosshatch" never reads the max-curvature angles: poisoning them
// with NaN changes nothing.
TEST(PencilInteriorReference, WithoutCrosshatchTheMaxDirectionsAreNeverRead) {
  Scene scene = testing::builtin_at("torus", 120, 90);
  Preprocessed pre = preprocess(scene, {"curvature", "pencil_textures"});
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height, pre.curvature);
  auto ip = scene.params.get<InteriorParams>();
  Image intensity = reference::interior_intensity(g, view_space_lights(scene), ip);
  Image before = reference::interior_darkness(g, intensity, pre.pencil_stack, {}, {false, false}, ip, 0);
  for (float& v : g.theta_max.data) v = NAN;
  Image after = reference::interior_darkness(g, intensity, pre.pencil_stack, {}, {false, false}, ip, 0);
  EXPECT_EQ(before.data, after.data);
  EXPECT_FALSE(has_non_finite(after));
}

TEST(PencilInteriorReference, DarkerIntensityGivesDarkerStrokesAndBackgroundStaysBlank) {
  Scene scene = testing::builtin_at("sphere", 100, 100);
  Preprocessed pre = preprocess(scene, {"curvature", "pencil_textures"});
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height, pre.curvature);
  auto ip = scene.params.get<InteriorParams>();
  auto mean_darkness = [&](float level) {
    Image intensity(100, 100, 1, level);
    Image d = reference::interior_darkness(g, intensity, pre.pencil_stack, {}, {false, false}, ip, 0);
    EXPECT_EQ(d.at(0, 0), 0.0f);  // background corner
    double sum = 0;
    for (float v : d.data) sum += v;
    return sum;
  };
  EXPECT_GT(mean_darkness(0.2f), mean_darkness(0.8f));
}

}  // namespace
}  // namespace plumbago
