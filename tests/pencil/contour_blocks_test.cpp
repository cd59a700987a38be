// The blocks of 8 x 8 pixels that multiple contour drawing skips (gpu/pencil/contour_blocks.hpp):
// a GPU-only saving, not a stage, so its check is against the definition: a block is
// marked where some pixel of it has d' > 0.
#include <gtest/gtest.h>

#include "common/scene/lights.hpp"
#include "gpu/pencil/contour_blocks.hpp"
#include "gpu/pencil/edge_detect.hpp"
#include "gpu/pencil/multi_contour.hpp"
#include "reference/scene/gbuffer.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// 1 for each block of kContourBlock x kContourBlock pixels holding some d' > 0, else 0.
Image blocks_holding_darkness(const Image& lit) {
  const int n = gpu::kContourBlock;
  Image marks((lit.width + n - 1) / n, (lit.height + n - 1) / n, 1);
  for (int y = 0; y < lit.height; ++y)
    for (int x = 0; x < lit.width; ++x)
      if (lit.at(x, y) > 0.0f) marks.at(x / n, y / n) = 1.0f;
  return marks;
}

class ContourBlocks : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

// A frame marks the blocks with some d' > 0 while it draws d' (edge_detect.frag, inside
// filter_rect; a clear outside it); multiple contour drawing alone finds them from d'
// (contour_blocks.frag). The marks must be the same, or a frame would skip contours (a
// mark missing) or compute pixels for nothing (a mark too many).
TEST_P(ContourBlocks, TheEdgePassMarksTheBlocksTheContoursPassFinds) {
  Scene scene = testing::square_and_torus(GetParam());
  gpu::GBufferTargets g = gpu::upload_gbuffer(reference::trace_gbuffer(scene, scene.width, scene.height));
  gpu::Texture lit = gpu::make_texture(scene.width, scene.height, GL_R32F);
  gpu::Texture marked = gpu::make_contour_block_marks(scene.width, scene.height);
  gpu::Texture found = gpu::make_contour_block_marks(scene.width, scene.height);
  gpu::EdgeDetectPass().run(g, scene.params.get<EdgeDetectParams>(), view_space_lights(scene),
                            scene.params.get<ContourLightParams>(), {lit, nullptr, &marked}, filter_rect(scene, 1));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  gpu::MultiContourPass().mark_blocks(lit, found);
  Image a = gpu::download_texture(marked, 1), b = gpu::download_texture(found, 1);
  double ones = 0;
  for (float v : b.data) ones += v;
  std::printf("[contour blocks, background %s] %zu blocks, %.0f marked\n", GetParam().c_str(), b.pixels(), ones);
  EXPECT_EQ(a.data, b.data);
  EXPECT_EQ(b.data, blocks_holding_darkness(gpu::download_texture(lit, 1)).data);
  EXPECT_GT(ones, 0.0);
  EXPECT_LT(ones, double(b.pixels()) * (GetParam() == "formula" ? 1.01 : 0.9));  // the background is unmarked
}

INSTANTIATE_TEST_SUITE_P(BackgroundPairs, ContourBlocks, ::testing::Values("continuous", "formula"));

}  // namespace
}  // namespace plumbago
