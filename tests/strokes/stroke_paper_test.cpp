// The paper effect of stroke-based rendering (Kalnins et al. 2002, §4.4): the transfer function, parity on
// a half-transparent coat, and the paper showing through it in a frame.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "common/strokes/stroke_paper.hpp"
#include "gpu/core/pipeline.hpp"
#include "parity/parity.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/parity_checks.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

StrokePaperParams defaults() { return ParamSet{}.get<StrokePaperParams>(); }

// With b = c = 1/2, h' = h and a' is the paper's t(a) = p(a) h + v(a)(1 - h).
TEST(StrokePaper, DefaultsGiveThePapersTransfer) {
  auto p = defaults();
  for (float h : {0.0f, 0.3f, 1.0f}) EXPECT_FLOAT_EQ(adjusted_height(h, p), h);
  EXPECT_FLOAT_EQ(paper_alpha(1.0f, 0.3f), 1.0f);    // opaque stays opaque
  EXPECT_FLOAT_EQ(paper_alpha(0.0f, 0.7f), 0.0f);    // nothing stays nothing
  EXPECT_FLOAT_EQ(paper_alpha(0.5f, 1.0f), 1.0f);    // a peak catches half a coat fully
  EXPECT_FLOAT_EQ(paper_alpha(0.5f, 0.0f), 0.0f);    // a valley resists it
  EXPECT_FLOAT_EQ(paper_alpha(0.25f, 0.5f), 0.25f);  // 0.5 sat(0.5) + 0.5 sat(-0.5)
}

TEST(StrokePaper, BrightnessAndContrastMoveTheHeight) {
  auto p = defaults();
  p.brightness = 1.0f;  // sat(2h): the upper half of the heights become peaks
  EXPECT_FLOAT_EQ(adjusted_height(0.6f, p), 1.0f);
  p.brightness = 0.5f;
  p.contrast = 0.0f;  // every height flattened to 1/2
  EXPECT_FLOAT_EQ(adjusted_height(0.9f, p), 0.5f);
  EXPECT_EQ(over_paper(glm::vec4(0.0f, 0.0f, 0.0f, 0.5f), glm::vec3(1.0f), 0.9f, p), glm::vec3(0.5f));
}

// A coat half transparent in the shadow: the paper decides how much of it each pixel keeps.
Scene translucent_coat(const std::string& name) {
  Scene scene = testing::builtin_at(name, 240, 180);
  scene = testing::drawn_with_strokes(scene);
  scene.params.set("basecoat.dark_a", 0.5);
  return scene;
}

class StrokePaperParity : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(StrokePaperParity, GpuMatchesReference) {
  Scene scene = translucent_coat(GetParam());
  auto results = run_parity(scene, {"stroke_paper"});
  ASSERT_EQ(testing::names_of(results), std::vector<std::string>{"stroke_paper.color"});
  const StageParity& r = results[0];
  std::printf("[stroke_paper %s] %s\n", GetParam().c_str(), format_diff(r.name, r.diff).c_str());
  EXPECT_EQ(r.diff.compared, size_t(scene.width) * size_t(scene.height));
  EXPECT_TRUE(r.pass) << r.note;
}

INSTANTIATE_TEST_SUITE_P(Scenes, StrokePaperParity, ::testing::Values("torus", "sphere", "cad"));

// In the half-transparent shadow the paper's grain shows: the shadow's pixels spread over
// many values between the tone and white; the opaque light tone stays one value.
class StrokePaperFrame : public testing::GlTest {};

TEST_F(StrokePaperFrame, ThePaperShowsThroughAHalfTransparentTone) {
  Scene scene = translucent_coat("sphere");
  for (const Frame& f : {reference::render(scene), gpu::Renderer(scene).render()}) {
    std::set<int> shadow_levels;
    int light = 0;
    for (size_t i = 0; i < f.color.pixels(); ++i) {
      float r = f.color.data[3 * i];
      if (r < 0.99f && r > 0.5f && std::abs(r - 0.93f) > 0.01f) shadow_levels.insert(int(r * 255.0f + 0.5f));
      light += std::abs(r - 0.93f) < 0.003f;
    }
    EXPECT_GT(shadow_levels.size(), 20u) << "no paper grain in the translucent shadow";
    EXPECT_GT(light, 100);
  }
}

}  // namespace
}  // namespace plumbago
