// Base coat (Kalnins et al. 2002, §4.2): parity on the built-in scenes, the formula on hand-made inputs,
// and what a frame of it looks like.
#include <gtest/gtest.h>

#include <cmath>

#include "common/strokes/basecoat.hpp"
#include "gpu/core/pipeline.hpp"
#include "parity/parity.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

Scene coat_scene(const std::string& name, const std::string& preset) {
  Scene scene = testing::builtin_at(name, 240, 180);
  scene = testing::drawn_with_strokes(scene);
  scene.params.set("basecoat.preset", preset);
  return scene;
}

class BaseCoatParity : public testing::GlTest,
                       public ::testing::WithParamInterface<std::tuple<std::string, std::string>> {};

// Both fed the reference G-buffer and the same per-vertex s; the 1D texture is read
// bilinearly (float weights on llvmpipe), the target is 8-bit.
TEST_P(BaseCoatParity, GpuMatchesReference) {
  auto [name, preset] = GetParam();
  Scene scene = coat_scene(name, preset);
  auto results = run_parity(scene, {"basecoat"});
  ASSERT_EQ(testing::names_of(results), std::vector<std::string>{"basecoat.coat"});
  const StageParity& r = results[0];
  std::printf("[basecoat %s %s] %s\n", name.c_str(), preset.c_str(), format_diff(r.name, r.diff).c_str());
  EXPECT_EQ(r.diff.compared, size_t(scene.width) * size_t(scene.height));
  EXPECT_TRUE(r.pass) << r.note;
}

INSTANTIATE_TEST_SUITE_P(Scenes, BaseCoatParity,
                         ::testing::Combine(::testing::Values("torus", "sphere", "cad"),
                                            ::testing::Values("toon", "smooth", "solid")));

TEST(BaseCoatTexture, PresetsAreTwoTonesARampOrOneColor) {
  ParamSet set;
  auto p = set.get<BaseCoatParams>();
  Image toon = basecoat_texture(p);
  ASSERT_EQ(toon.width, kBaseCoatTexels);
  ASSERT_EQ(toon.channels, 4);
  EXPECT_FLOAT_EQ(toon.at(0, 0, 0), p.dark_r);
  EXPECT_FLOAT_EQ(toon.at(kBaseCoatTexels - 1, 0, 0), p.light_r);
  int split = 0;  // the first light texel: its center is at or past the threshold
  while (toon.at(split, 0, 0) == p.dark_r) ++split;
  EXPECT_EQ(split, int(std::ceil(p.threshold * kBaseCoatTexels - 0.5f)));
  p.preset = BaseCoatPreset::Smooth;
  Image smooth = basecoat_texture(p);
  EXPECT_NEAR(smooth.at(128, 0, 1), p.dark_g + (p.light_g - p.dark_g) * (128.5f / 256.0f), 1e-6);
  p.preset = BaseCoatPreset::Solid;
  for (float v : basecoat_texture(p).data)
    EXPECT_TRUE(v == p.light_r || v == p.light_g || v == p.light_b || v == p.light_a);
}

// One triangle facing the only light: s = 1 at every corner; turned away, s = -1, or 1
// with |n.L|.
TEST(BaseCoatShades, EachCornerSumsItsLightsNDotL) {
  Scene scene = parse_scene(
      R"({"mesh": {"procedural": "sphere"}, "lights": [{"direction": [0, 0, 1], "intensity": 1}]})", "test:coat", ".");
  ParamSet set;
  auto p = set.get<BaseCoatParams>();
  TriangleShades s = triangle_shades(scene, p);
  ASSERT_EQ(s.first_triangle, std::vector<uint32_t>{0});
  ASSERT_FALSE(s.corners.empty());
  float lowest = 1, highest = -1;
  for (const glm::vec4& c : s.corners)
    for (int k = 0; k < 3; ++k) lowest = std::min(lowest, c[k]), highest = std::max(highest, c[k]);
  EXPECT_LT(lowest, -0.99f);  // the far side of the sphere
  EXPECT_GT(highest, 0.99f);
  p.abs_n_dot_l = true;
  for (const glm::vec4& c : triangle_shades(scene, p).corners)
    for (int k = 0; k < 3; ++k) EXPECT_GE(c[k], 0.0f);
}

// A toon-shaded sphere lit from the camera's side: both tones (opaque, so the paper effect
// leaves them as they are), white around it, on both backends; nothing of the pencil
// pipeline runs.
class BaseCoatFrame : public testing::GlTest {};

TEST_F(BaseCoatFrame, AToonSphereHasBothTonesOnWhite) {
  Scene scene = coat_scene("sphere", "toon");
  auto p = scene.params.get<BaseCoatParams>();
  for (const Frame& f : {reference::render(scene), gpu::Renderer(scene).render()}) {
    int dark = 0, light = 0;
    for (size_t i = 0; i < f.color.pixels(); ++i) {
      dark += std::abs(f.color.data[3 * i] - p.dark_r) < 0.01f;
      light += std::abs(f.color.data[3 * i] - p.light_r) < 0.01f;
    }
    EXPECT_GT(dark, 100);
    EXPECT_GT(light, 100);
    EXPECT_EQ(f.color.at(0, 0, 0), 1.0f) << "the background is white paper";
    std::vector<std::string> names;
    for (const PassTime& t : f.ran) names.push_back(t.name);
    EXPECT_EQ(std::count(names.begin(), names.end(), "compose"), 0) << "the pencil pipeline ran";
  }
}

}  // namespace
}  // namespace plumbago
