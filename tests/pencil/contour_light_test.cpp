// Contour lighting (Lee et al. 2006, §4.1, Eq. 1): GPU vs reference on the same inputs, and Eq. 1 itself.
#include <gtest/gtest.h>

#include "parity/parity.hpp"
#include "reference/pencil/contour_light.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

class ContourLightParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

// Same float formula on the same inputs; measured max abs ~1e-7 on llvmpipe.
TEST_P(ContourLightParity, GpuMatchesReference) {
  Scene scene = testing::builtin_at(GetParam(), 240, 180);
  auto results = run_parity(scene, {"contour_light"});
  ASSERT_EQ(testing::names_of(results), testing::kEdgeAndLightResults);
  const StageParity& r = results[1];
  std::printf("[contour_light %s] %s\n", GetParam().c_str(), format_diff(r.name, r.diff).c_str());
  EXPECT_TRUE(r.pass);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ContourLightParity, ::testing::Values("torus", "sphere", "cad"));

TEST(ContourLightReference, LitContoursAreLighterByLambda) {
  GBuffer g;
  g.normal = Image(3, 1, 3);
  g.normal.at(0, 0, 2) = 1;   // facing the light
  g.normal.at(1, 0, 2) = -1;  // facing away
  Image d(3, 1, 1, 1.0f);     // pixel 2: background normal (0,0,0)
  ParamSet set;
  set.set("contour_light.light_influence", 0.4);
  Image lit = reference::lit_contour_darkness(d, g, {{{0, 0, 1}, 1.0f}}, set.get<ContourLightParams>());
  EXPECT_FLOAT_EQ(lit.at(0, 0), 0.6f);
  EXPECT_FLOAT_EQ(lit.at(1, 0), 1.0f);
  EXPECT_FLOAT_EQ(lit.at(2, 0), 1.0f);
}

}  // namespace
}  // namespace plumbago
