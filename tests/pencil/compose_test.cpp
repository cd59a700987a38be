// Composition and enhancement (Lee et al. 2006, §6, Eq. 6, stage `compose`): GPU vs reference on the same
// inputs, and the formula of common/pencil/compose.hpp on hand-made images with known answers:
//   D_i' = D_i (1 - a D_c),  I = (1 - D_c)(1 - D_i'),
//   I'' = mix(I, smoothstep(0, 1, I), contrast),  out = I'' c_p.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/core/params.hpp"
#include "parity/parity.hpp"
#include "reference/pencil/compose.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// ---------------------------------------------------------------------------------
// Parity: both backends fed the reference contours (alone, then multiple contours drawn
// in the composition pass itself), an interior and the paper color; 8-bit target.

// The composition pass alone, then drawing the multiple contours itself (a frame's way).
const std::vector<std::string> kComposeResults = {"compose.color",
                                                  "multi_contour.contour_darkness in multi_contour+compose",
                                                  "compose.color in multi_contour+compose"};

void expect_compose_parity(const std::vector<StageParity>& results, const Scene& scene, const std::string& label) {
  ASSERT_EQ(testing::names_of(results), kComposeResults) << label;
  for (const StageParity& r : results) {
    std::printf("[%s %s] %s\n", r.name.c_str(), label.c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_EQ(r.diff.compared, size_t(scene.width) * size_t(scene.height)) << r.name;
    EXPECT_TRUE(r.pass) << r.name << ": " << r.note;
    EXPECT_FALSE(has_non_finite(r.gpu)) << r.name;
  }
}

class ComposeParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(ComposeParity, GpuMatchesReference) {
  Scene scene = testing::builtin_at(GetParam(), 320, 240);
  expect_compose_parity(run_parity(scene, {"compose"}), scene, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, ComposeParity, ::testing::Values("torus", "sphere", "cad"));

TEST_F(ComposeParity, Fandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  Scene scene = testing::model_scene("fandisk.obj", 400, 400);
  expect_compose_parity(run_parity(scene, {"compose"}), scene, "fandisk");
}

// The parameters reach both backends: away from the defaults the images change, and the
// GPU still matches.
TEST_F(ComposeParity, ParametersReachBothBackends) {
  Scene defaults = testing::builtin_at("cad", 320, 240), changed = defaults;
  changed.params.set("compose.contour_attenuation", 1.0);
  changed.params.set("compose.contrast", 0.0);
  auto before = run_parity(defaults, {"compose"}), after = run_parity(changed, {"compose"});
  expect_compose_parity(after, changed, "cad, attenuation 1, contrast 0");
  ASSERT_EQ(testing::names_of(before), kComposeResults);
  ASSERT_EQ(testing::names_of(after), kComposeResults);
  for (size_t i = 0; i < before.size(); ++i) {
    if (before[i].name.rfind(kComposeColor.name, 0) != 0) continue;  // D_c does not read them
    EXPECT_NE(before[i].reference.data, after[i].reference.data) << before[i].name;
    EXPECT_NE(before[i].gpu.data, after[i].gpu.data) << before[i].name;
  }
}

// ---------------------------------------------------------------------------------
// The formula (reference/pencil/compose.hpp) on tiny images

ComposeParams compose_params(double attenuation, double contrast) {
  ParamSet set;
  set.set("compose.contour_attenuation", attenuation);
  set.set("compose.contrast", contrast);
  return set.get<ComposeParams>();
}

// A w x h paper whose texel (x, y) is (r, g, b) + (x, y, 0) / 100: each texel told apart.
Image numbered_paper(int w, int h, float r, float g, float b) {
  Image paper(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      paper.at(x, y, 0) = r + float(x) / 100;
      paper.at(x, y, 1) = g + float(y) / 100;
      paper.at(x, y, 2) = b;
    }
  return paper;
}

// No contours and no interior: I = 1, smoothstep(1) = 1, so the output is the paper color,
// read texel for pixel and wrapping (a 2 x 3 tile under a 5 x 4 image).
TEST(ComposeReference, NothingDrawnGivesThePaperColorTiled) {
  Image paper = numbered_paper(2, 3, 0.9f, 0.8f, 0.7f);
  Image none(5, 4, 1, 0.0f);
  for (const Image& interior : {Image(), Image(5, 4, 1, 0.0f)}) {  // no interior, and a blank one
    Image out = reference::compose(none, interior, paper, ParamSet{}.get<ComposeParams>());
    ASSERT_EQ(out.width, 5);
    ASSERT_EQ(out.height, 4);
    ASSERT_EQ(out.channels, 3);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(out.at(x, y, c), paper.at(x % 2, y % 3, c)) << x << "," << y << "," << c;
  }
}

// Without a paper image the paper is white: nothing drawn gives exactly 1.
TEST(ComposeReference, NoPaperIsWhite) {
  Image out = reference::compose(Image(3, 2, 1, 0.0f), Image(), Image(), ParamSet{}.get<ComposeParams>());
  ASSERT_EQ(out.data.size(), 3u * 2u * 3u);
  for (float v : out.data) EXPECT_EQ(v, 1.0f);
}

// D_c = 1: I = 0 whatever the interior, attenuation, contrast and paper: black.
TEST(ComposeReference, FullContourDarknessIsBlack) {
  Image paper = numbered_paper(2, 2, 0.9f, 0.8f, 0.7f);
  for (float interior : {0.0f, 0.3f, 1.0f})
    for (double a : {0.0, 0.5, 1.0})
      for (double contrast : {0.0, 0.5, 1.0}) {
        Image out =
            reference::compose(Image(2, 2, 1, 1.0f), Image(2, 2, 1, interior), paper, compose_params(a, contrast));
        for (float v : out.data) EXPECT_EQ(v, 0.0f) << "D_i " << interior << " a " << a << " contrast " << contrast;
      }
}

// D_i = 1 without contours: I = 0, black too (the interior alone can reach black).
TEST(ComposeReference, FullInteriorDarknessWithoutContoursIsBlack) {
  Image out = reference::compose(Image(2, 2, 1, 0.0f), Image(2, 2, 1, 1.0f), Image(), ParamSet{}.get<ComposeParams>());
  for (float v : out.data) EXPECT_EQ(v, 0.0f);
}

// Contrast 0 leaves I; contrast 1 gives smoothstep(I) = I^2 (3 - 2I); between, the mix.
// Interior only (D_c = 0): I = 1 - D_i.
TEST(ComposeReference, ContrastMixesIWithItsSmoothstep) {
  const float d_i = 0.6f;  // I = 0.4, smoothstep(0.4) = 0.16 * 2.2 = 0.352
  auto at = [&](double contrast) {
    return reference::compose(Image(1, 1, 1, 0.0f), Image(1, 1, 1, d_i), Image(), compose_params(0.5, contrast))
        .at(0, 0, 0);
  };
  EXPECT_NEAR(at(0.0), 0.4f, 1e-6f);
  EXPECT_NEAR(at(1.0), 0.352f, 1e-6f);
  EXPECT_NEAR(at(0.5), 0.376f, 1e-6f);
  EXPECT_NEAR(at(0.25), 0.388f, 1e-6f);
}

// The contours fade the interior strokes under them: D_i' = D_i (1 - a D_c).
// D_c = 0.5, D_i = 1, contrast 0: a = 0 gives I = 0.5 * 0 = 0; a = 1 gives
// D_i' = 0.5, I = 0.25; a = 0.5 gives D_i' = 0.75, I = 0.125.
TEST(ComposeReference, ContoursAttenuateTheInteriorUnderThem) {
  auto at = [&](double a) {
    return reference::compose(Image(1, 1, 1, 0.5f), Image(1, 1, 1, 1.0f), Image(), compose_params(a, 0.0)).at(0, 0, 0);
  };
  EXPECT_NEAR(at(0.0), 0.0f, 1e-6f);
  EXPECT_NEAR(at(1.0), 0.25f, 1e-6f);
  EXPECT_NEAR(at(0.5), 0.125f, 1e-6f);
}

// One pixel worked through at the defaults (a = 0.5, contrast 0.5), on a colored paper:
//   D_c = 0.5, D_i = 0.4:  D_i' = 0.4 (1 - 0.25) = 0.3,  I = 0.5 * 0.7 = 0.35,
//   smoothstep(0.35) = 0.1225 * 2.3 = 0.28175,  I'' = (0.35 + 0.28175) / 2 = 0.315875,
//   out = 0.315875 * (1, 0.5, 0.25).
TEST(ComposeReference, AWorkedPixelAtTheDefaults) {
  auto p = ParamSet{}.get<ComposeParams>();
  ASSERT_EQ(p.contour_attenuation, 0.5f);
  ASSERT_EQ(p.contrast, 0.5f);
  Image paper(1, 1, 3);
  paper.data = {1.0f, 0.5f, 0.25f};
  Image out = reference::compose(Image(1, 1, 1, 0.5f), Image(1, 1, 1, 0.4f), paper, p);
  EXPECT_NEAR(out.at(0, 0, 0), 0.315875f, 1e-6f);
  EXPECT_NEAR(out.at(0, 0, 1), 0.1579375f, 1e-6f);
  EXPECT_NEAR(out.at(0, 0, 2), 0.07896875f, 1e-6f);
}

// Each pixel is composed from its own D_c and D_i: a 2 x 1 image of two different pixels
// gives each pixel what a 1 x 1 image of it gives.
TEST(ComposeReference, EachPixelFromItsOwnInputs) {
  auto p = ParamSet{}.get<ComposeParams>();
  Image contours(2, 1, 1), interior(2, 1, 1);
  contours.data = {0.2f, 0.9f};
  interior.data = {0.7f, 0.1f};
  Image paper = numbered_paper(2, 1, 0.9f, 0.8f, 0.7f);
  Image both = reference::compose(contours, interior, paper, p);
  for (int x = 0; x < 2; ++x) {
    Image texel(1, 1, 3);
    for (int c = 0; c < 3; ++c) texel.at(0, 0, c) = paper.at(x, 0, c);
    Image one = reference::compose(Image(1, 1, 1, contours.data[size_t(x)]), Image(1, 1, 1, interior.data[size_t(x)]),
                                   texel, p);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(both.at(x, 0, c), one.at(0, 0, c)) << x << "," << c;
  }
  EXPECT_LT(both.at(1, 0, 0), both.at(0, 0, 0));  // the darker contour is the darker pixel
}

}  // namespace
}  // namespace plumbago
