// The GPU runs its window-space passes only where their output can differ from the
// background's (common/scene/scene.hpp filter_rect, common/pencil/distortion.hpp contour_rect,
// common/sketchy/sketchy.hpp composite_rect) and clears the rest (composition copies the blank page there). A small
// square seen face-on makes those rectangles exact, so any margin too small shows up in the parity of the passes
// against the reference, which computes every pixel.
#include <gtest/gtest.h>

#include "common/util/image_compare.hpp"
#include "gpu/pencil/compose.hpp"
#include "gpu/pencil/multi_contour.hpp"
#include "parity/parity.hpp"
#include "reference/pencil/multi_contour.hpp"
#include "reference/scene/gbuffer.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

class SkippedPixels : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SkippedPixels, PassesMatchTheReferenceInsideAndOutside) {
  Scene scene = testing::square_and_torus(GetParam());
  auto results = run_parity(
      scene, {"edge_detect", "contour_light", "multi_contour", "interior_intensity", "pencil_interior", "compose"});
  // each GPU pass once: multi_contour and compose alone and in one pass
  std::vector<std::string> expected = testing::kEdgeAndLightResults;
  expected.insert(expected.end(), testing::kInteriorResults.begin(), testing::kInteriorResults.end());
  expected.insert(expected.end(),
                  {"multi_contour.contour_darkness", "multi_contour.contour_darkness in multi_contour+compose",
                   "compose.color in multi_contour+compose", "compose.color"});
  ASSERT_EQ(testing::names_of(results), expected);
  for (const auto& r : results) {
    std::printf("[skipped pixels, background %s] %s\n", GetParam().c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name << ": " << r.note;
  }
}

INSTANTIATE_TEST_SUITE_P(BackgroundPairs, SkippedPixels, ::testing::Values("continuous", "formula"));

// Multiple contour drawing also skips the pixels whose copies can only read d' = 0, found
// by blocks of 8 x 8 pixels (gpu/pencil/multi_contour.cpp). Single dots of d' on the first and
// last texel of a block, read by two copies shifted by the whole reach each way, put
// the farthest pixel a copy can darken right past a block's edge: a reach cut by a pixel
// misses it.
TEST_F(SkippedPixels, MultiContourFindsDotsAtTheFullReachOfTheOffsets) {
  auto p = testing::untextured_contours(2, 8);
  Image lit(72, 56, 1, 0.0f);
  for (auto [x, y] : {std::pair{16, 16}, {31, 31}, {40, 47}, {55, 8}}) lit.at(x, y) = 1.0f;
  const float reach = 5.3f;  // a fraction of a texel: the farthest read has weight 0.3
  std::vector<Image> grids;
  for (float sign : {1.0f, -1.0f}) grids.push_back(Image(10, 8, 2, sign * reach));
  std::vector<glm::vec2> shifts(2, glm::vec2(0));
  Image texture(4, 4, 1, 1.0f);

  Image expected = reference::multi_contour_darkness(lit, grids, texture, shifts, p);
  gpu::ContourInputs inputs = gpu::make_contour_inputs(p, grids, texture, shifts, lit.width, lit.height);
  gpu::Texture in = gpu::upload_texture(lit, GL_R32F), out = gpu::make_texture(lit.width, lit.height, GL_R32F);
  PixelRect window{0, 0, lit.width, lit.height};
  gpu::MultiContourPass pass;
  pass.run(in, inputs, p, out, window);
  // The same drawn in the composition pass, as a frame does (its second output is D_c).
  gpu::Texture color = gpu::make_texture(lit.width, lit.height, GL_RGBA8),
               in_compose = gpu::make_texture(lit.width, lit.height, GL_R32F);
  gpu::Texture none = gpu::make_texture(1, 1, GL_R32F);
  gpu::ComposePass().run(pass.prepare(in, inputs, p), {none, false, none, false}, ParamSet{}.get<ComposeParams>(),
                         color, window, &in_compose);
  for (const gpu::Texture* t : {&out, &in_compose}) {
    ImageDiff d = compare_images(expected, gpu::download_texture(*t, 1), 1e-5);
    std::printf("[skipped pixels, dots at the reach] %s\n",
                format_diff(t == &out ? "multi_contour" : "multi_contour.in_compose", d).c_str());
    EXPECT_EQ(d.over_tolerance, 0.0);
  }
  EXPECT_NEAR(expected.at(10, 10), 0.3f * 0.3f * p.stroke_opacity, 1e-5f);  // the dot at (16, 16), read from 5.3 px
}

}  // namespace
}  // namespace plumbago
