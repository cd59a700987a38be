// Pencil textures (SPEC 1.2; Lee Eq. 3-4): tones, tiling, white preservation,
// determinism. Small tiles keep the suite fast; the formula does not depend on size.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "common/params.hpp"
#include "common/pencil_texture.hpp"

namespace plumbago {
namespace {

PencilParams small_stack() {
  ParamSet set;
  set.set("pencil.size", 128.0);
  set.set("pencil.layers", 16.0);
  return set.get<PencilParams>();
}

double mean(const Image& img) { return std::accumulate(img.data.begin(), img.data.end(), 0.0) / double(img.data.size()); }

TEST(PencilTexture, LayerZeroIsWhiteAndTonesFallUniformly) {
  PencilParams p = small_stack();
  auto layers = pencil_layers(p, 1);
  ASSERT_EQ(int(layers.size()), p.layers);
  for (float v : layers[0].data) ASSERT_EQ(v, 1.0f);
  for (int l = 1; l < p.layers; ++l) {
    double m = mean(layers[size_t(l)]), target = layer_target(p, l);
    EXPECT_LT(m, mean(layers[size_t(l) - 1])) << "layer " << l;
    EXPECT_NEAR(m, target, 0.02 * target) << "layer " << l;
  }
  std::printf("[pencil] darkest layer mean %.4f (target %.4f)\n", mean(layers.back()), layer_target(p, p.layers - 1));
}

// The tile wraps: the jump across the seam (last column to first, top row to bottom) is
// no larger than the jump between neighbors inside the tile.
TEST(PencilTexture, TilesWrapWithoutASeam) {
  PencilParams p = small_stack();
  const Image img = pencil_layers(p, 3)[8];
  auto column_jump = [&](int a, int b) {
    double s = 0;
    for (int y = 0; y < img.height; ++y) s += std::abs(img.at(a, y) - img.at(b, y));
    return s / img.height;
  };
  auto row_jump = [&](int a, int b) {
    double s = 0;
    for (int x = 0; x < img.width; ++x) s += std::abs(img.at(x, a) - img.at(x, b));
    return s / img.width;
  };
  double inside_x = 0, inside_y = 0;
  for (int i = 0; i + 1 < img.width; ++i) inside_x += column_jump(i, i + 1) / (img.width - 1);
  for (int i = 0; i + 1 < img.height; ++i) inside_y += row_jump(i, i + 1) / (img.height - 1);
  EXPECT_LT(column_jump(img.width - 1, 0), 1.5 * inside_x);
  EXPECT_LT(row_jump(img.height - 1, 0), 1.5 * inside_y);
}

TEST(PencilTexture, WhitePreservationKeepsMoreWhiteTexels) {
  PencilParams p = small_stack();
  auto white_share = [&](float mu_w) {
    PencilParams q = p;
    q.mu_w = mu_w;
    const Image img = pencil_layers(q, 5)[4];
    return double(std::count_if(img.data.begin(), img.data.end(), [&](float v) { return v > q.white_level; })) /
           double(img.data.size());
  };
  double with = white_share(0.4f), without = white_share(1.0f);
  std::printf("[pencil] texels above white_level at the same tone: mu_w=0.4 %.3f, mu_w=1 %.3f\n", with, without);
  EXPECT_GT(with, without + 0.01);
}

TEST(PencilTexture, SameSeedSameTexturesOtherSeedOtherStrokes) {
  PencilParams p = small_stack();
  EXPECT_EQ(pencil_layers(p, 9)[5].data, pencil_layers(p, 9)[5].data);
  EXPECT_NE(pencil_layers(p, 9)[5].data, pencil_layers(p, 10)[5].data);
}

}  // namespace
}  // namespace plumbago
