// Distorted planes (Lee Eq. 2): bounded offsets, the requested period, the
// noise term's spread, distinct and reproducible copies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/core/params.hpp"
#include "common/pencil/distortion.hpp"

namespace plumbago {
namespace {

ContourParams contour_params(std::vector<std::pair<std::string, double>> overrides = {}) {
  ParamSet set;
  for (const auto& [key, value] : overrides) set.set(key, value);
  return set.get<ContourParams>();
}

TEST(Distortion, OneGridPerCopyCoveringTheWindow) {
  auto p = contour_params();
  auto grids = distortion_grids(p, 800, 600, 1);
  ASSERT_EQ(int(grids.size()), p.copies);
  for (const auto& g : grids) {
    EXPECT_EQ(g.channels, 2);
    EXPECT_EQ(g.width, 800 / p.grid_cell + 1);                       // 800 = 50 cells exactly
    EXPECT_EQ(g.height, (600 + p.grid_cell - 1) / p.grid_cell + 1);  // 600 needs a 38th cell
  }
}

TEST(Distortion, OffsetsAreBoundedByAmplitudePlusNoise) {
  auto p = contour_params();
  float largest = 0;
  for (const auto& g : distortion_grids(p, 800, 600, 1))
    for (float v : g.data) {
      EXPECT_LE(std::abs(v), p.shake_amplitude + p.shake_noise + 1e-5f);
      largest = std::max(largest, std::abs(v));
    }
  std::printf("[distortion] largest offset %.3f px, bound a + r = %.3f px\n", largest,
              p.shake_amplitude + p.shake_noise);
  EXPECT_GT(largest, p.shake_amplitude);  // the sine's peaks plus some noise reach past a
}

// With the noise off, dx depends on y alone through sin(b y + c) and dy on x alone:
// vertices one period apart carry the same offsets, vertices half a period apart the
// opposite ones.
TEST(Distortion, PeriodicPartHasTheRequestedPeriod) {
  auto p = contour_params({{"contour.shake_noise", 0.0}, {"contour.shake_period", 64.0}, {"contour.grid_cell", 16.0}});
  for (const Image& g : distortion_grids(p, 512, 512, 4)) {
    for (int j = 0; j + 4 < g.height; ++j) {  // 4 cells = 64 px
      EXPECT_NEAR(g.at(3, j, 0), g.at(3, j + 4, 0), 1e-4f);
      EXPECT_NEAR(g.at(3, j, 0), -g.at(3, j + 2, 0), 1e-4f);
      EXPECT_NEAR(g.at(3, j, 0), g.at(7, j, 0), 1e-6f);  // dx does not depend on x
    }
    for (int i = 0; i + 4 < g.width; ++i) {
      EXPECT_NEAR(g.at(i, 5, 1), g.at(i + 4, 5, 1), 1e-4f);
      EXPECT_NEAR(g.at(i, 5, 1), g.at(i, 9, 1), 1e-6f);  // dy does not depend on y
    }
    EXPECT_GT(std::abs(g.at(3, 0, 0) - g.at(3, 1, 0)), 1e-3f);
  }
}

// With the sine off, offsets are r xi with xi uniform in [-1, 1]: mean |offset| = r / 2.
TEST(Distortion, NoiseTermIsUniformWithinR) {
  auto p = contour_params({{"contour.shake_amplitude", 0.0}});
  double sum = 0, count = 0;
  for (const auto& g : distortion_grids(p, 1024, 1024, 2))
    for (float v : g.data) sum += std::abs(v), ++count;
  std::printf("[distortion] mean |r xi| %.4f px, expected r / 2 = %.4f px\n", sum / count, p.shake_noise / 2);
  EXPECT_NEAR(sum / count, p.shake_noise / 2, 0.05 * p.shake_noise);
}

TEST(Distortion, CopiesDifferAndRepeatWithTheSeed) {
  auto p = contour_params();
  auto grids = distortion_grids(p, 256, 256, 1);
  for (size_t a = 0; a < grids.size(); ++a)
    for (size_t b = a + 1; b < grids.size(); ++b) EXPECT_NE(grids[a].data, grids[b].data) << a << " vs " << b;
  EXPECT_EQ(distortion_grids(p, 256, 256, 1)[1].data, grids[1].data);
  EXPECT_NE(distortion_grids(p, 256, 256, 2)[1].data, grids[1].data);
  auto shifts = contour_texture_shifts(p, 1);
  ASSERT_EQ(int(shifts.size()), p.copies);
  EXPECT_NE(shifts[0], shifts[1]);
  EXPECT_EQ(contour_texture_shifts(p, 1), shifts);
}

}  // namespace
}  // namespace plumbago
