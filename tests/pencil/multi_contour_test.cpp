// Multiple contour drawing (Lee et al. 2006, §4.2-4.3): GPU vs reference on the same inputs, and the
// formula's own properties.
#include <gtest/gtest.h>

#include "parity/parity.hpp"
#include "reference/pencil/multi_contour.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// Multiple contour drawing as its own pass, then drawn in the composition pass.
const std::vector<std::string> kMultiContourResults = {"multi_contour.contour_darkness",
                                                       "multi_contour.contour_darkness in multi_contour+compose",
                                                       "compose.color in multi_contour+compose"};

class MultiContourParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(MultiContourParity, GpuMatchesReference) {
  Scene scene = testing::builtin_at(GetParam(), 320, 240);
  // Its own pass, then drawn in the composition pass (a frame's way).
  auto results = run_parity(scene, {"multi_contour"});
  ASSERT_EQ(testing::names_of(results), kMultiContourResults);
  for (const StageParity& r : results) {
    std::printf("[multi_contour %s] %s\n", GetParam().c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, MultiContourParity, ::testing::Values("torus", "cad"));

TEST_F(MultiContourParity, FiveCopiesOnFandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  Scene scene = testing::model_scene("fandisk.obj", 400, 400);
  scene.params.set("contour.copies", 5.0);
  auto results = run_parity(scene, {"multi_contour"});
  ASSERT_EQ(testing::names_of(results), kMultiContourResults);
  for (const StageParity& r : results) {
    std::printf("[multi_contour fandisk 5 copies] %s\n", format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name;
  }
}

// Without shaking and texture, k copies of a line of darkness d give 1 - (1 - alpha d)^k.
TEST(MultiContourReference, OverlappingCopiesDarkenAsAProduct) {
  auto p = testing::untextured_contours(3, 16);
  Image lit(16, 16, 1, 0.5f);
  std::vector<Image> still(3, Image(3, 3, 2, 0.0f));
  std::vector<glm::vec2> shifts(3, glm::vec2(0));
  Image out = reference::multi_contour_darkness(lit, still, Image(4, 4, 1, 1.0f), shifts, p);
  float expected = 1.0f - std::pow(1.0f - p.stroke_opacity * 0.5f, 3.0f);
  EXPECT_NEAR(out.at(7, 7), expected, 1e-6f);
}

// A shift of the grid moves the contour: a one-pixel line lands `dx` pixels away.
TEST(MultiContourReference, OffsetsMoveTheContour) {
  auto p = testing::untextured_contours(1, 4);
  Image lit(16, 16, 1, 0.0f);
  for (int y = 0; y < 16; ++y) lit.at(8, y) = 1.0f;
  Image shift(5, 5, 2, 0.0f);
  for (int i = 0; i < 25; ++i) shift.data[size_t(i) * 2] = 3.0f;  // dx = 3 px everywhere
  Image out = reference::multi_contour_darkness(lit, {shift}, Image(4, 4, 1, 1.0f), {glm::vec2(0)}, p);
  EXPECT_NEAR(out.at(5, 8), p.stroke_opacity, 1e-6f);  // reads the line at x = 5 + 3
  EXPECT_NEAR(out.at(8, 8), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace plumbago
