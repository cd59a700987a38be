// Interior intensity and brightness (Lee et al. 2006, §3, §5.2): GPU vs reference on the same G-buffer,
// Gouraud and Phong, with and without the brightness adjustment.
#include <gtest/gtest.h>

#include "parity/parity.hpp"
#include "reference/pencil/interior_intensity.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

class InteriorIntensityParity : public testing::GlTest,
                                public ::testing::WithParamInterface<std::tuple<std::string, std::string, bool>> {};

// Same float formula on the same inputs; measured max abs ~1e-7 on llvmpipe (the
// reference renormalizes the light direction, the shader receives it unit).
TEST_P(InteriorIntensityParity, GpuMatchesReference) {
  auto [scene_name, shading, sqrt_on] = GetParam();
  Scene scene = testing::builtin_at(scene_name, 240, 180);
  scene.params.set("interior.shading", shading);
  scene.params.set("interior.brightness_sqrt", sqrt_on ? 1.0 : 0.0);
  auto results = run_parity(scene, {"interior_intensity"});
  ASSERT_EQ(testing::names_of(results), testing::kInteriorResults);
  const StageParity& r = results[0];
  std::printf("[interior_intensity %s %s sqrt=%d] %s\n", scene_name.c_str(), shading.c_str(), int(sqrt_on),
              format_diff(r.name, r.diff).c_str());
  EXPECT_TRUE(r.pass);
}

INSTANTIATE_TEST_SUITE_P(Scenes, InteriorIntensityParity,
                         ::testing::Combine(::testing::Values("torus", "cad"), ::testing::Values("gouraud", "phong"),
                                            ::testing::Bool()));

TEST(InteriorIntensityReference, BrightnessIsTheSquareRootAndBackgroundIsWhite) {
  GBuffer g;
  g.normal = Image(2, 1, 3);
  g.normal.at(0, 0, 2) = 1;
  g.depth = Image(2, 1, 1, 5);
  g.gouraud = Image(2, 1, 1, 0.25f);
  g.ids = ImageU32(2, 1, 2, 0);
  g.ids.at(0, 0, 0) = 1;
  ParamSet set;
  Image out = reference::interior_intensity(g, {}, set.get<InteriorParams>());
  EXPECT_FLOAT_EQ(out.at(0, 0), 0.5f);  // sqrt(0.25)
  EXPECT_FLOAT_EQ(out.at(1, 0), 1.0f);  // background
  set.set("interior.shading", std::string("phong"));
  set.set("interior.brightness_sqrt", std::string("false"));
  set.set("interior.ambient", 0.25);
  set.set("interior.diffuse", 0.5);
  out = reference::interior_intensity(g, {{{0, 0, 1}, 1.0f}}, set.get<InteriorParams>());
  EXPECT_FLOAT_EQ(out.at(0, 0), 0.75f);  // k_a + k_d (n.L = 1, head-on)
}

}  // namespace
}  // namespace plumbago
