// Interior pencil shading (Lee et al. 2006, §5.1-5.5): GPU vs reference on the same inputs, and the
// effect switches. The composition with interior and paper: compose_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "common/core/preprocess.hpp"
#include "common/scene/lights.hpp"
#include "parity/parity.hpp"
#include "reference/pencil/interior_intensity.hpp"
#include "reference/pencil/pencil_interior.hpp"
#include "reference/scene/gbuffer.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const std::vector<std::string>& kPencilInteriorResults = testing::kInteriorResults;
// Lee et al. 2006, §5.1-5.4 alone, then with cross hatching (2.9) and the paper effect (2.10).
const std::vector<std::vector<std::string>> kInteriorEffects = {{"contours", "interior"},
                                                                {"contours", "interior", "crosshatch", "paper"}};

class PencilInteriorParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

// Bilinear/trilinear lookups of the pencil stack at rotated coordinates; measured max
// abs 7e-6 on llvmpipe (float textures are filtered with float weights).
TEST_P(PencilInteriorParity, GpuMatchesReference) {
  Scene scene = testing::builtin_at(GetParam(), 320, 240);
  for (const auto& effects : kInteriorEffects) {
    scene.effects = effects;
    auto results = run_parity(scene, {"pencil_interior"});
    ASSERT_EQ(testing::names_of(results), kPencilInteriorResults);
    for (const StageParity& r : results) {
      std::printf("[%s %s, %zu effects] %s\n", r.name.c_str(), GetParam().c_str(), effects.size(),
                  format_diff(r.name, r.diff).c_str());
      EXPECT_TRUE(r.pass) << r.name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PencilInteriorParity, ::testing::Values("torus", "sphere", "cad"));

TEST_F(PencilInteriorParity, Fandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  Scene scene = testing::model_scene("fandisk.obj", 400, 400);
  for (const auto& effects : kInteriorEffects) {
    scene.effects = effects;
    auto results = run_parity(scene, {"pencil_interior"});
    ASSERT_EQ(testing::names_of(results), kPencilInteriorResults);
    for (const StageParity& r : results) {
      std::printf("[%s fandisk, %zu effects] %s\n", r.name.c_str(), effects.size(),
                  format_diff(r.name, r.diff).c_str());
      EXPECT_TRUE(r.pass) << r.name;
    }
  }
}

// The ablation of Lee Fig. 6 on both backends: one texture per pixel, from the corner of
// largest weight.
TEST_F(PencilInteriorParity, NearestCornerBlendMatchesReference) {
  Scene scene = testing::builtin_at("cad", 320, 240);
  scene.params.set("interior.blend", std::string("nearest_corner"));
  auto results = run_parity(scene, {"pencil_interior"});
  ASSERT_EQ(testing::names_of(results), kPencilInteriorResults);
  for (const StageParity& r : results) {
    std::printf("[%s cad nearest_corner] %s\n", r.name.c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name;
  }
}

TEST(PencilInteriorBlend, NearestCornerKeepsOnlyTheLargestWeight) {
  ParamSet params;
  auto ip = params.get<InteriorParams>();
  glm::vec3 w(0.2f, 0.5f, 0.3f);
  EXPECT_EQ(blend_weights(w, ip), w);
  ip.blend = InteriorBlend::NearestCorner;
  EXPECT_EQ(blend_weights(w, ip), glm::vec3(0, 1, 0));
  EXPECT_EQ(blend_weights(glm::vec3(0.1f, 0.2f, 0.7f), ip), glm::vec3(0, 0, 1));
  EXPECT_EQ(blend_weights(glm::vec3(0.4f, 0.4f, 0.2f), ip), glm::vec3(1, 0, 0));  // a tie: the first
}

// A builtin scene's reference inputs to the pencil interior: curvature, pencil stack,
// G-buffer with corner angles, and its interior intensity.
struct ReferenceInterior {
  Scene scene;
  Preprocessed pre = preprocess(scene, {"curvature", "pencil_textures"});
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height, pre.get(kCurvature));
  InteriorParams ip = scene.params.get<InteriorParams>();
  Image intensity = reference::interior_intensity(g, view_space_lights(scene), ip);

  // D_i without cross hatching or paper, for `p` (default: the scene's parameters).
  Image darkness(const InteriorParams& p) const {
    return reference::interior_darkness(g, intensity, pre.get(kPencilStack), {}, {false, false}, p, 0);
  }
};

// Three-way blending removes the seams of one texture per corner (Lee §5.4): where the
// corner of largest weight changes between two neighbors inside one triangle, the
// nearest-corner image jumps from one rotated texture to another; the blend does not.
TEST(PencilInteriorBlend, ThreeWayBlendingIsSmootherThanNearestCorner) {
  const ReferenceInterior in{testing::builtin_at("torus", 240, 180)};
  const GBuffer& g = in.g;
  InteriorParams ip = in.ip, one_corner = in.ip;
  one_corner.blend = InteriorBlend::NearestCorner;
  auto largest = [&](int x, int y) {
    return blend_weights(glm::vec3(g.bary.at(x, y, 0), g.bary.at(x, y, 1), g.bary.at(x, y, 2)), one_corner);
  };
  auto seam_jump = [&](InteriorBlend blend) {  // mean |d(x+1) - d(x)| across those seams
    ip.blend = blend;
    Image d = in.darkness(ip);
    double sum = 0;
    int n = 0;
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x + 1 < d.width; ++x)
        if (!g.background(x, y) && !g.background(x + 1, y) && g.ids.at(x, y, 1) == g.ids.at(x + 1, y, 1) &&
            largest(x, y) != largest(x + 1, y)) {
          sum += std::abs(d.at(x + 1, y) - d.at(x, y));
          ++n;
        }
    EXPECT_GT(n, 100);
    return sum / n;
  };
  double three_way = seam_jump(InteriorBlend::ThreeWay), nearest = seam_jump(InteriorBlend::NearestCorner);
  std::printf("[blend] mean darkness jump across nearest-corner seams: three_way %.4f, nearest_corner %.4f\n",
              three_way, nearest);
  EXPECT_LT(three_way, nearest);
}

// "interior" without "crosshatch" never reads the max-curvature angles: poisoning them
// with NaN changes nothing.
TEST(PencilInteriorReference, WithoutCrosshatchTheMaxDirectionsAreNeverRead) {
  ReferenceInterior in{testing::builtin_at("torus", 120, 90)};
  Image before = in.darkness(in.ip);
  for (float& v : in.g.theta_max.data) v = NAN;
  Image after = in.darkness(in.ip);
  EXPECT_EQ(before.data, after.data);
  EXPECT_FALSE(has_non_finite(after));
}

TEST(PencilInteriorReference, DarkerIntensityGivesDarkerStrokesAndBackgroundStaysBlank) {
  Scene scene = testing::builtin_at("sphere", 100, 100);
  Preprocessed pre = preprocess(scene, {"curvature", "pencil_textures"});
  GBuffer g = reference::trace_gbuffer(scene, scene.width, scene.height, pre.get(kCurvature));
  auto ip = scene.params.get<InteriorParams>();
  auto mean_darkness = [&](float level) {
    Image intensity(100, 100, 1, level);
    Image d = reference::interior_darkness(g, intensity, pre.get(kPencilStack), {}, {false, false}, ip, 0);
    EXPECT_EQ(d.at(0, 0), 0.0f);  // background corner
    double sum = 0;
    for (float v : d.data) sum += v;
    return sum;
  };
  EXPECT_GT(mean_darkness(0.2f), mean_darkness(0.8f));
}

}  // namespace
}  // namespace plumbago
