// Paper (Lee et al. 2006, §5.5): height range and spread, tiling, normals as the formula says,
// color between its two ends, roughness that follows the parameters, determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "common/core/params.hpp"
#include "common/pencil/paper.hpp"

namespace plumbago {
namespace {

PaperParams small_paper(double size = 128) {
  ParamSet set;
  set.set("paper.size", size);
  return set.get<PaperParams>();
}

glm::vec3 normal_at(const Paper& paper, int x, int y) {
  const float* n = paper.normal.pixel(x, y);
  return {n[0], n[1], n[2]};
}

// Mean |h(x+1, y) - h(x, y)| over the tile, wrapping: how rough the height field is.
double mean_step(const Image& h) {
  double s = 0;
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) s += std::abs(h.at((x + 1) % h.width, y) - h.at(x, y));
  return s / double(h.pixels());
}

// h is rescaled to span [0, 1] exactly; a sum of noises has its mass in the middle.
TEST(Paper, HeightSpansZeroToOneWithItsMassInTheMiddle) {
  Paper paper = make_paper(small_paper(), 1);
  auto [lo, hi] = std::minmax_element(paper.height.data.begin(), paper.height.data.end());
  EXPECT_EQ(*lo, 0.0f);
  EXPECT_EQ(*hi, 1.0f);
  double sum = 0, sum_sq = 0;
  for (float h : paper.height.data) sum += h, sum_sq += double(h) * h;
  double n = double(paper.height.data.size()), mean = sum / n, var = sum_sq / n - mean * mean;
  std::printf("[paper] height mean %.3f variance %.4f\n", mean, var);
  EXPECT_GT(mean, 0.3);
  EXPECT_LT(mean, 0.7);
  EXPECT_GT(var, 0.005);       // not flat
  EXPECT_LT(var, 1.0 / 12.0);  // less spread than uniform on [0, 1]
}

// n = normalize(-dh/dx s, -dh/dy s, 1) with periodic central differences, checked at the
// tile's corners (where the differences wrap) and inside.
TEST(Paper, NormalsAreUnitAndFollowTheHeightSlope) {
  PaperParams p = small_paper();
  Paper paper = make_paper(p, 1);
  const Image& h = paper.height;
  int last = h.width - 1;
  for (auto [x, y] : {std::pair{0, 0}, {last, last}, {0, last}, {37, 81}}) {
    float dx = (h.at((x + 1) % h.width, y) - h.at((x + last) % h.width, y)) / 2;
    float dy = (h.at(x, (y + 1) % h.height) - h.at(x, (y + last) % h.height)) / 2;
    glm::vec3 expected = glm::normalize(glm::vec3(-dx * p.bumpiness, -dy * p.bumpiness, 1));
    glm::vec3 n = normal_at(paper, x, y);
    EXPECT_NEAR(glm::distance(n, expected), 0.0f, 1e-5f) << x << "," << y;
  }
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      ASSERT_NEAR(glm::length(normal_at(paper, x, y)), 1.0f, 1e-5f);
      ASSERT_GT(normal_at(paper, x, y).z, 0.0f);
    }
  p.bumpiness = 0;
  Paper flat = make_paper(p, 1);
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) ASSERT_EQ(normal_at(flat, x, y), glm::vec3(0, 0, 1));
}

// The step across each seam (last column to first, top row to bottom) is like a step
// inside the tile.
TEST(Paper, TilesWithoutASeam) {
  Paper paper = make_paper(small_paper(), 2);
  const Image& h = paper.height;
  double seam_x = 0, seam_y = 0;
  for (int i = 0; i < h.width; ++i) {
    seam_x += std::abs(h.at(h.width - 1, i) - h.at(0, i)) / h.height;
    seam_y += std::abs(h.at(i, h.height - 1) - h.at(i, 0)) / h.width;
  }
  double inside = mean_step(h);
  std::printf("[paper] mean step across seams %.4f %.4f, inside %.4f\n", seam_x, seam_y, inside);
  EXPECT_LT(seam_x, 1.5 * inside);
  EXPECT_LT(seam_y, 1.5 * inside);
}

// Finer noise (more lattice cells, more cellular fibres) makes neighbors differ more.
TEST(Paper, RoughnessFollowsTheNoiseFrequency) {
  PaperParams coarse = small_paper(), fine = small_paper();
  coarse.base_period = 4;
  coarse.worley_cells = 8;
  fine.base_period = 16;
  fine.worley_cells = 32;
  double rough_coarse = mean_step(make_paper(coarse, 3).height), rough_fine = mean_step(make_paper(fine, 3).height);
  std::printf("[paper] mean neighbor step: coarse %.4f, fine %.4f\n", rough_coarse, rough_fine);
  EXPECT_GT(rough_fine, 1.5 * rough_coarse);
}

TEST(Paper, ColorIsTheMixOfValleyAndPeakByHeight) {
  PaperParams p = small_paper();
  Paper paper = make_paper(p, 3);
  glm::vec3 valley(p.valley_r, p.valley_g, p.valley_b), peak(p.peak_r, p.peak_g, p.peak_b);
  for (size_t i = 0; i < paper.height.pixels(); ++i) {
    glm::vec3 expected = glm::mix(valley, peak, paper.height.data[i]);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(paper.color.data[i * 3 + size_t(c)], expected[c], 1e-6f);
  }
}

TEST(Paper, SameSeedSamePaperOtherSeedOther) {
  PaperParams p = small_paper(64);
  EXPECT_EQ(make_paper(p, 4).normal.data, make_paper(p, 4).normal.data);
  EXPECT_NE(make_paper(p, 4).height.data, make_paper(p, 5).height.data);
}

}  // namespace
}  // namespace plumbago
