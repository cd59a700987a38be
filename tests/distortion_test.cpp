// Distorted planes (SPEC 1.4, Lee Eq. 2): bounded offsets, the requested period,
// distinct copies.
#include <gtest/gtest.h>

#include <cmath>

#include "common/distortion.hpp"
#include "common/params.hpp"

namespace plumbago {
namespace {

TEST(Distortion, OffsetsAreBoundedByAmplitudePlusNoise) {
  auto p = ParamSet{}.get<ContourParams>();
  auto grids = distortion_grids(p, 800, 600, 1);
  ASSERT_EQ(int(grids.size()), p.copies);
  EXPECT_EQ(grids[0].width, 800 / p.grid_cell + 1);
  EXPECT_EQ(grids[0].height, (600 + p.grid_cell - 1) / p.grid_cell + 1);
  for (const auto& g : grids)
    for (float v : g.data) EXPECT_LE(std::abs(v), p.shake_amplitude + p.shake_noise + 1e-5f);
}

// With the noise off, dx depends on y alone through sin(b y + c): rows one period apart
// carry the same offsets.
TEST(Distortion, PeriodicPartHasTheRequestedPeriod) {
  ParamSet set;
  set.set("contour.shake_noise", 0.0);
  set.set("contour.shake_period", 64.0);
  set.set("contour.grid_cell", 16.0);
  auto p = set.get<ContourParams>();
  const Image g = distortion_grids(p, 512, 512, 4)[0];
  for (int j = 0; j + 4 < g.height; ++j) EXPECT_NEAR(g.at(3, j, 0), g.at(3, j + 4, 0), 1e-4f);  // 4 cells = 64 px
  EXPECT_GT(std::abs(g.at(3, 0, 0) - g.at(3, 1, 0)), 1e-3f);
}

TEST(Distortion, CopiesDiffer) {
  auto p = ParamSet{}.get<ContourParams>();
  auto grids = distortion_grids(p, 256, 256, 1);
  EXPECT_NE(grids[0].data, grids[1].data);
  EXPECT_EQ(distortion_grids(p, 256, 256, 1)[1].data, grids[1].data);
}

}  // namespace
}  // namespace plumbago
