// Pencil textures (Lee Eq. 3-4): tones, tiling, white preservation,
// determinism. Small tiles keep the suite fast where the formula does not depend on size.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "common/core/params.hpp"
#include "common/pencil/pencil_textures.hpp"

namespace plumbago {
namespace {

PencilTexturesParams small_stack() {
  ParamSet set;
  set.set("pencil_textures.size", 128.0);
  set.set("pencil_textures.layers", 16.0);
  return set.get<PencilTexturesParams>();
}

double mean(const Image& img) {
  return std::accumulate(img.data.begin(), img.data.end(), 0.0) / double(img.data.size());
}

// The default stack, as the renderers use it.
TEST(PencilTexture, LayerZeroIsWhiteAndTonesFallUniformly) {
  auto p = ParamSet{}.get<PencilTexturesParams>();
  auto layers = pencil_layers(p, 1);
  ASSERT_EQ(int(layers.size()), p.layers);
  for (float v : layers[0].data) ASSERT_EQ(v, 1.0f);
  double worst = 0;
  for (int l = 1; l < p.layers; ++l) {
    double m = mean(layers[size_t(l)]), target = layer_target(p, l);
    EXPECT_LT(m, mean(layers[size_t(l) - 1])) << "layer " << l;
    EXPECT_NEAR(m, target, 0.02 * target) << "layer " << l;
    worst = std::max(worst, std::abs(m - target) / target);
  }
  std::printf("[pencil] largest relative miss of a layer's tone target: %.4f%%\n", 100 * worst);
  std::printf("[pencil] darkest layer mean %.4f (target %.4f)\n", mean(layers.back()), layer_target(p, p.layers - 1));
}

// Eq. 3-4 as Lee et al. 2006, §5.1, Eq. 3-4 writes them, on numbers worked by hand (mu_b 0.2, mu_w 0.4,
// white_level 0.9).
TEST(PencilTexture, GraphiteUpdateIsEquations3And4) {
  auto p = ParamSet{}.get<PencilTexturesParams>();
  ASSERT_FLOAT_EQ(p.mu_b, 0.2f);
  ASSERT_FLOAT_EQ(p.mu_w, 0.4f);
  EXPECT_NEAR(graphite_update(p, 1.0f, 0.3f), 1.0f - 0.2f * 0.4f * 0.7f, 1e-6f);  // white: preserved
  EXPECT_NEAR(graphite_update(p, 0.5f, 0.3f), 0.5f - 0.2f * 0.5f * 0.7f, 1e-6f);  // gray: full mu_b
  EXPECT_NEAR(graphite_update(p, 0.9f, 0.0f), 0.9f - 0.2f * 0.9f, 1e-6f);         // at the level: not white
  EXPECT_EQ(graphite_update(p, 0.7f, 1.0f), 0.7f);                                // c_s = 1: no graphite
}

// Strokes only darken: every texel of a layer is at most its value one layer up, and
// all stay in [0, 1]. A stack cut at `last` is the start of the whole stack.
TEST(PencilTexture, LayersDarkenTexelByTexelAndPrefixesMatch) {
  PencilTexturesParams p = small_stack();
  auto layers = pencil_layers(p, 2);
  for (size_t l = 1; l < layers.size(); ++l)
    for (size_t i = 0; i < layers[l].data.size(); ++i) {
      ASSERT_LE(layers[l].data[i], layers[l - 1].data[i]) << "layer " << l << " texel " << i;
      ASSERT_GE(layers[l].data[i], 0.0f);
    }
  auto prefix = pencil_layers(p, 2, 6);
  ASSERT_EQ(prefix.size(), 7u);
  EXPECT_EQ(prefix.back().data, layers[6].data);
}

// The tile wraps: the jump across the seam (last column to first, top row to bottom) is
// no larger than the jump between neighbors inside the tile.
TEST(PencilTexture, TilesWrapWithoutASeam) {
  PencilTexturesParams p = small_stack();
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
  std::printf("[pencil] mean step across seams %.4f %.4f, inside %.4f %.4f\n", column_jump(img.width - 1, 0),
              row_jump(img.height - 1, 0), inside_x, inside_y);
  EXPECT_LT(column_jump(img.width - 1, 0), 1.5 * inside_x);
  EXPECT_LT(row_jump(img.height - 1, 0), 1.5 * inside_y);
}

// Eq. 4: at the same tone, the light layers keep more texels above white_level than
// they do with preservation off (mu_w = 1).
TEST(PencilTexture, WhitePreservationKeepsMoreWhiteTexels) {
  PencilTexturesParams p = small_stack();
  auto white_shares = [&](float mu_w) {
    PencilTexturesParams q = p;
    q.mu_w = mu_w;
    std::vector<double> shares;
    for (const Image& img : pencil_layers(q, 5, 4)) {
      auto white = std::count_if(img.data.begin(), img.data.end(), [&](float v) { return v > q.white_level; });
      shares.push_back(double(white) / double(img.data.size()));
    }
    return shares;
  };
  auto with = white_shares(p.mu_w), without = white_shares(1.0f);
  for (size_t l = 1; l < with.size(); ++l) {
    std::printf("[pencil] layer %zu, texels above white_level: mu_w=%.1f %.3f, mu_w=1 %.3f\n", l, p.mu_w, with[l],
                without[l]);
    EXPECT_GT(with[l], without[l] + 0.02) << "layer " << l;
  }
}

TEST(PencilTexture, SameSeedSameTexturesOtherSeedOtherStrokes) {
  PencilTexturesParams p = small_stack();
  EXPECT_EQ(pencil_layers(p, 9)[5].data, pencil_layers(p, 9)[5].data);
  EXPECT_NE(pencil_layers(p, 9)[5].data, pencil_layers(p, 10)[5].data);
}

// A tone no stroke can reach is refused with the keys to change, not looped on forever.
TEST(PencilTexture, UnreachableToneIsRefused) {
  PencilTexturesParams p = small_stack();
  p.mu_b = 0;
  EXPECT_THROW(pencil_layers(p, 1, 1), std::runtime_error);
  p = small_stack();
  p.darkest = 0;
  try {
    pencil_layers(p, 1);
    ADD_FAILURE() << "mean 0 reached";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("pencil_textures.darkest"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plumbago
