// Tileable noise (common/util/noise.hpp): periodic with its integer period, bounded,
// deterministic; the sketchy noise texture wraps and spans [-1, 1].
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/core/params.hpp"
#include "common/util/noise.hpp"

namespace plumbago {
namespace {

// Points spread over a few periods, off the lattice.
std::vector<glm::vec2> sample_points(float extent) {
  std::vector<glm::vec2> pts;
  for (int j = 0; j < 23; ++j)
    for (int i = 0; i < 23; ++i) pts.push_back({extent * (float(i) + 0.37f) / 23, extent * (float(j) + 0.61f) / 23});
  return pts;
}

TEST(Noise, PerlinRepeatsWithItsPeriodAndStaysInBounds) {
  TileablePerlin n(7, 1, "test-perlin");
  float largest = 0;
  for (glm::vec2 p : sample_points(7)) {
    float v = n(p);
    largest = std::max(largest, std::abs(v));
    EXPECT_NEAR(v, n(p + glm::vec2(7, 0)), 1e-5f);
    EXPECT_NEAR(v, n(p + glm::vec2(0, -14)), 1e-5f);
    EXPECT_LE(std::abs(v), std::sqrt(0.5f) + 1e-6f);
  }
  EXPECT_GT(largest, 0.2f);                                       // not flat
  EXPECT_NEAR(n(glm::vec2(3, 5)), 0.0f, 1e-6f);                   // 0 at lattice points
  EXPECT_NE(n(glm::vec2(0.5f, 0.5f)), n(glm::vec2(3.5f, 0.5f)));  // cells differ within a period
}

TEST(Noise, FbmAndWorleyWrapOverTheUnitTile) {
  auto octaves = fbm_octaves(3, 4, 2, "test-fbm");
  TileableWorley worley(5, 2, "test-worley");
  for (glm::vec2 uv : sample_points(1)) {
    EXPECT_NEAR(fbm(octaves, uv), fbm(octaves, uv + glm::vec2(1, 1)), 1e-4f);
    EXPECT_NEAR(worley(uv), worley(uv + glm::vec2(-1, 0)), 1e-5f);
    EXPECT_NEAR(worley(uv), worley(uv + glm::vec2(0, 1)), 1e-5f);
    EXPECT_GE(worley(uv), 0.0f);
    EXPECT_LE(worley(uv), std::sqrt(2.0f));  // the own cell's point is never farther
  }
}

TEST(Noise, SameSeedAndNameSameNoiseOtherwiseOther) {
  glm::vec2 p(1.3f, 2.7f);
  EXPECT_EQ(TileablePerlin(8, 1, "a")(p), TileablePerlin(8, 1, "a")(p));
  EXPECT_NE(TileablePerlin(8, 1, "a")(p), TileablePerlin(8, 2, "a")(p));
  EXPECT_NE(TileablePerlin(8, 1, "a")(p), TileablePerlin(8, 1, "b")(p));
  EXPECT_NE(TileableWorley(8, 1, "a")(p / 8.0f), TileableWorley(8, 2, "a")(p / 8.0f));
}

TEST(Noise, SketchyNoiseTextureWrapsAndSpansItsRange) {
  auto p = ParamSet{}.get<NoiseTextureParams>();
  Image img = perlin_noise_texture(p, 1);
  ASSERT_EQ(img.width, p.size);
  double sum = 0, seam = 0, inside = 0;
  auto [lo, hi] = std::minmax_element(img.data.begin(), img.data.end());
  for (float v : img.data) sum += v;
  for (int y = 0; y < img.height; ++y) {
    seam += std::abs(img.at(img.width - 1, y) - img.at(0, y));
    for (int x = 0; x + 1 < img.width; ++x) inside += std::abs(img.at(x, y) - img.at(x + 1, y)) / (img.width - 1);
  }
  std::printf("[noise] sketchy noise range [%.3f, %.3f], mean %.4f, seam/interior step %.3f\n", *lo, *hi,
              sum / double(img.data.size()), seam / inside);
  EXPECT_GE(*lo, -1.0f);
  EXPECT_LE(*hi, 1.0f);
  EXPECT_LT(*lo, -0.5f);  // p.period^2 cells: some reach well into both halves
  EXPECT_GT(*hi, 0.5f);
  EXPECT_NEAR(sum / double(img.data.size()), 0.0, 0.1);
  EXPECT_LT(seam, 1.5 * inside);
  EXPECT_EQ(perlin_noise_texture(p, 1).data, img.data);
  EXPECT_NE(perlin_noise_texture(p, 2).data, img.data);
}

}  // namespace
}  // namespace plumbago
