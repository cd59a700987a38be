// Stroke textures (Kalnins et al. 2002, §4.1): determinism, range, tiling in u, the soft cross-section,
// and the three kinds' order in mean and variance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/strokes/stroke_textures.hpp"

namespace plumbago {
namespace {

const StrokeTextureKind kKinds[] = {StrokeTextureKind::Pencil, StrokeTextureKind::Charcoal, StrokeTextureKind::Ink};

struct Moments {
  double mean, variance;
};

// Mean and variance over rows [y0, y1).
Moments row_moments(const Image& t, int y0, int y1) {
  double sum = 0, sum_sq = 0, n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < t.width; ++x) sum += t.at(x, y), sum_sq += double(t.at(x, y)) * t.at(x, y), ++n;
  double mean = sum / n;
  return {mean, sum_sq / n - mean * mean};
}

// The middle half of the rows, clear of the cross-section's falloff.
Moments middle_moments(const Image& t) { return row_moments(t, t.height / 4, 3 * t.height / 4); }

TEST(StrokeTextures, SizeAndRange) {
  for (StrokeTextureKind kind : kKinds) {
    Image t = stroke_texture(kind, 1);
    EXPECT_EQ(t.width, kStrokeTextureWidth);
    EXPECT_EQ(t.height, kStrokeTextureHeight);
    EXPECT_EQ(t.channels, 1);
    auto [lo, hi] = std::minmax_element(t.data.begin(), t.data.end());
    EXPECT_GE(*lo, 0.0f);
    EXPECT_LE(*hi, 1.0f);
  }
  EXPECT_EQ(stroke_texture_names(), (std::vector<std::string>{"pencil", "charcoal", "ink"}));
}

TEST(StrokeTextures, SameSeedSameTextureOtherSeedAnother) {
  for (StrokeTextureKind kind : kKinds) {
    EXPECT_EQ(stroke_texture(kind, 7).data, stroke_texture(kind, 7).data);
    EXPECT_NE(stroke_texture(kind, 7).data, stroke_texture(kind, 8).data);
  }
}

// GL_REPEAT in u: across the seam (last column to first) the texture changes no more
// than between neighbouring columns elsewhere. Without tiling the streaks, tens of
// texels long, would jump there by about their whole contrast.
TEST(StrokeTextures, TilesInU) {
  for (StrokeTextureKind kind : kKinds) {
    Image t = stroke_texture(kind, 3);
    double seam = 0, neighbours = 0;
    for (int y = 0; y < t.height; ++y) {
      seam += std::abs(t.at(0, y) - t.at(t.width - 1, y));
      for (int x = 0; x + 1 < t.width; ++x) neighbours += std::abs(t.at(x + 1, y) - t.at(x, y));
    }
    seam /= t.height;
    neighbours /= double(t.height) * (t.width - 1);
    std::printf("[stroke_textures] %s: seam step %.4f, mean step %.4f\n", stroke_texture_names()[int(kind)].c_str(),
                seam, neighbours);
    EXPECT_LE(seam, 2 * neighbours + 1e-6);
  }
}

// The soft edge that replaces GL_LINE_SMOOTH: ~0 on the outermost rows, growing towards
// the middle, full in the middle half.
TEST(StrokeTextures, CrossSectionFallsOffAtBothSides) {
  for (StrokeTextureKind kind : kKinds) {
    Image t = stroke_texture(kind, 1);
    double middle = middle_moments(t).mean;
    int top = t.height - 1;
    for (int y : {0, top}) EXPECT_LT(row_moments(t, y, y + 1).mean, 0.05) << y;
    EXPECT_LT(row_moments(t, 0, 2).mean, row_moments(t, 2, 4).mean);
    EXPECT_LT(row_moments(t, top - 1, top + 1).mean, row_moments(t, top - 3, top - 1).mean);
    EXPECT_LT(row_moments(t, 2, 4).mean, middle);
    EXPECT_LT(row_moments(t, top - 3, top - 1).mean, middle);
    EXPECT_GT(middle, 0.3);
  }
}

// Ink is the most solid (highest mean, least variance), charcoal the most broken (lowest
// mean, most variance), pencil between.
TEST(StrokeTextures, KindsOrderInMeanAndVariance) {
  Moments pencil = middle_moments(stroke_texture(StrokeTextureKind::Pencil, 1));
  Moments charcoal = middle_moments(stroke_texture(StrokeTextureKind::Charcoal, 1));
  Moments ink = middle_moments(stroke_texture(StrokeTextureKind::Ink, 1));
  std::printf("[stroke_textures] mean/variance: pencil %.3f/%.4f charcoal %.3f/%.4f ink %.3f/%.4f\n", pencil.mean,
              pencil.variance, charcoal.mean, charcoal.variance, ink.mean, ink.variance);
  EXPECT_GT(ink.mean, pencil.mean);
  EXPECT_GT(pencil.mean, charcoal.mean);
  EXPECT_GT(ink.mean, 0.85);
  EXPECT_LT(ink.variance, 0.005);
  EXPECT_GT(charcoal.variance, pencil.variance);
  EXPECT_GT(pencil.variance, ink.variance);
}

}  // namespace
}  // namespace plumbago
