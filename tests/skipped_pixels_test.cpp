// The GPU runs its window-space passes only where their output can differ from the
// background's (common/scene.hpp filter_rect, common/distortion.hpp contour_rect,
// common/sketchy.hpp composite_rect) and clears the rest. A small square seen face-on
// makes those rectangles exact, so any margin too small shows up in the parity of the
// passes against the reference, which computes every pixel.
#include <gtest/gtest.h>

#include "apps/parity.hpp"
#include "tests/test_scenes.hpp"

namespace plumbago {
namespace {

class SkippedPixels : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SkippedPixels, PassesMatchTheReferenceInsideAndOutside) {
  std::string json = R"({"objects": [{"mesh": {"procedural": "plane"},
      "transform": [0.3, 0, 0, 0,  0, 0.3, 0, 0,  0, 0, 0.3, 0,  0.9, 0.5, 0.2, 1]},
      {"mesh": {"procedural": "torus"}, "transform": [0.5, 0, 0, 0,  0, 0.5, 0, 0,  0, 0, 0.5, 0,  -0.6, -0.4, 0, 1]}],
    "camera": {"view_direction": [0, 0, 1]}, "effects": ["contours", "interior"], "resolution": [240, 180],
    "params": {"edge.background_pairs": ")" + GetParam() + R"("}})";
  Scene scene = parse_scene(json, "test:skipped", ".");
  auto results = run_parity(scene, {"edge_detect", "contour_light", "multi_contour", "interior_intensity", "pencil_interior"});
  ASSERT_EQ(results.size(), 6u);
  for (const auto& r : results) {
    std::printf("[skipped pixels, background %s] %s\n", GetParam().c_str(), format_diff(r.name, r.diff).c_str());
    EXPECT_TRUE(r.pass) << r.name << ": " << r.note;
  }
}

INSTANTIATE_TEST_SUITE_P(BackgroundPairs, SkippedPixels, ::testing::Values("continuous", "formula"));

}  // namespace
}  // namespace plumbago
