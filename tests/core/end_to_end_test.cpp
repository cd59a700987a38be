// End to end (docs/conventions.md): whole frames from both backends, each from its own G-buffer.
#include <gtest/gtest.h>

#include "parity/parity.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

const std::vector<std::string> kPencil = {"contours", "interior", "crosshatch", "paper"};

void expect_frames_agree(const Scene& scene, const std::string& label) {
  auto r = run_parity(scene, {"end_to_end"}).at(0);
  std::printf("[end_to_end %s] within 2/255: %.2f%% of pixels; %s\n", label.c_str(), 100 * (1 - r.diff.over_tolerance),
              format_diff(r.name, r.diff).c_str());
  EXPECT_TRUE(r.pass) << label;
}

void expect_end_to_end(Scene scene, const std::string& label) {
  scene.effects = kPencil;
  expect_frames_agree(scene, label);
}

class EndToEnd : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(EndToEnd, BuiltinScene) { expect_end_to_end(testing::builtin_at(GetParam(), 320, 240), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Builtin, EndToEnd, ::testing::Values("torus", "sphere", "cad"));

TEST_F(EndToEnd, Fandisk) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  expect_end_to_end(testing::model_scene("fandisk.obj", 400, 400), "fandisk");
}

TEST_F(EndToEnd, StanfordBunny) {
  PLUMBAGO_REQUIRE_MODEL("stanford-bunny.obj");
  expect_end_to_end(testing::model_scene("stanford-bunny.obj", 400, 400), "stanford-bunny");
}

// A stroke sphere behind a sketchy plane, no pencil effect: the sketch is drawn over white
// paper, not over a pencil frame that did not run (the GPU's page was black there).
TEST_F(EndToEnd, StrokeAndSketchyObjectsWithoutPencilEffects) {
  expect_frames_agree(parse_scene(R"({"objects": [
      {"mesh": {"procedural": "sphere"}, "style": "strokes"},
      {"mesh": {"procedural": "plane"}, "style": "sketchy",
       "transform": [2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 1.5, 1]}],
      "resolution": [320, 240], "effects": ["strokes"],
      "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40}})",
                                  "strokes and sketchy", "."),
                      "strokes and sketchy");
}

}  // namespace
}  // namespace plumbago
