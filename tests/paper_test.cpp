// Paper (SPEC 1.3): range, unit normals, tiling, color between its two ends.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "common/paper.hpp"
#include "common/params.hpp"

namespace plumbago {
namespace {

PaperParams small_paper() {
  ParamSet set;
  set.set("paper.size", 128.0);
  return set.get<PaperParams>();
}

TEST(Paper, HeightSpansZeroToOneWithSpreadAndUnitNormals) {
  Paper paper = make_paper(small_paper(), 1);
  double sum = 0, sum_sq = 0;
  for (float h : paper.height.data) {
    ASSERT_GE(h, 0.0f);
    ASSERT_LE(h, 1.0f);
    sum += h, sum_sq += double(h) * h;
  }
  double n = double(paper.height.data.size()), mean = sum / n, var = sum_sq / n - mean * mean;
  std::printf("[paper] height mean %.3f variance %.4f\n", mean, var);
  EXPECT_GT(mean, 0.2);  // min-max normalized noise: neither end dominates
  EXPECT_LT(mean, 0.8);
  EXPECT_GT(var, 0.005);
  for (size_t i = 0; i < paper.normal.pixels(); ++i) {
    glm::vec3 v(paper.normal.data[i * 3], paper.normal.data[i * 3 + 1], paper.normal.data[i * 3 + 2]);
    ASSERT_NEAR(glm::length(v), 1.0f, 1e-5f);
    ASSERT_GT(v.z, 0.0f);
  }
}

TEST(Paper, TilesWithoutASeam) {
  Paper paper = make_paper(small_paper(), 2);
  const Image& h = paper.height;
  double seam = 0, inside = 0;
  for (int y = 0; y < h.height; ++y) {
    seam += std::abs(h.at(h.width - 1, y) - h.at(0, y));
    inside += std::abs(h.at(h.width / 2, y) - h.at(h.width / 2 + 1, y));
  }
  EXPECT_LT(seam, 2.0 * inside);
}

TEST(Paper, ColorLiesBetweenValleyAndPeak) {
  PaperParams p = small_paper();
  Paper paper = make_paper(p, 3);
  for (size_t i = 0; i < paper.height.pixels(); ++i) {
    float expected = p.valley_r + (p.peak_r - p.valley_r) * paper.height.data[i];
    ASSERT_NEAR(paper.color.data[i * 3], expected, 1e-5f);
  }
}

}  // namespace
}  // namespace plumbago
