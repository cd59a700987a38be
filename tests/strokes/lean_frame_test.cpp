// A GPU strokes frame that keeps nothing whole (gpu::Renderer::render_frame, the bench's) reads
// nothing back once a frame has sized the stroke steps' buffers: the GPU completes the path
// table (gpu/strokes/row_counts.hpp TableRows) and every step goes over it by its header's
// dispatches. It draws what the sizing frame drew of the same view; where a frame needs more
// than the buffers hold, the steps keep within them, and the next frame that sizes them draws
// it whole.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/scene/scene.hpp"
#include "common/strokes/decal.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/strokes/row_counts.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

class LeanFrames : public testing::GlTest {};

// Scenes whose frames have every kind of window path: creases, borders, silhouettes, decals
// and hatches, moving hatching groups among them.
std::vector<std::string> scene_files() {
  return {"teapot_decals.json", "hatching_lod.json", "snowman_mobile.json", "storefront_strokes.json",
          "torus_strokes.json"};
}

// The largest difference of two images of one size, over every channel.
float largest_difference(const Image& a, const Image& b) {
  float most = 0;
  for (size_t i = 0; i < a.data.size(); ++i) most = std::max(most, std::abs(a.data[i] - b.data[i]));
  return most;
}

TEST_F(LeanFrames, ReadNothingBackAndDrawWhatTheSizingFrameDrew) {
  for (const std::string& file : scene_files()) {
    Scene s = load_scene(PLUMBAGO_SOURCE_DIR "/scenes/" + file);
    gpu::Renderer renderer(s);
    const Image sized = renderer.render().color;
    for (int k = 0; k < 2; ++k) {
      Frame lean;
      renderer.render_frame(lean);
      EXPECT_EQ(lean.readback_bytes, 0u) << file;
      const Image drawn = renderer.color();
      ASSERT_EQ(drawn.data.size(), sized.data.size()) << file;
      EXPECT_EQ(largest_difference(drawn, sized), 0.0f) << file << ", lean frame " << k;
    }
  }
}

// The first frame of a renderer sizes the buffers even when it is a lean one, and reads back
// only what the GPU counted of its paths (gpu/strokes/row_counts.hpp: 48 bytes, and 32 per
// line style, one a decal).
TEST_F(LeanFrames, TheFirstFrameSizesTheBuffers) {
  Scene s = load_scene(PLUMBAGO_SOURCE_DIR "/scenes/teapot_decals.json");
  gpu::Renderer lean_first(s);
  Frame first, second;
  lean_first.render_frame(first);
  EXPECT_EQ(first.readback_bytes, gpu::RowCounts::bytes(3 + decal_samples(s).size()));
  lean_first.render_frame(second);
  EXPECT_EQ(second.readback_bytes, 0u);
  const Image drawn = lean_first.color();
  EXPECT_EQ(largest_difference(drawn, gpu::Renderer(s).render().color), 0.0f);
}

// Visibility sampled 32 times as often as when the buffers were sized (strokes.vis_step_px,
// read each frame): the lean frame keeps within them (no GL error, nothing read back) and
// leaves strokes out, and the next render() draws what a renderer made for the new value does.
TEST_F(LeanFrames, SamplesThatOutgrowTheBuffersKeepWithinThem) {
  for (const char* file : {"teapot_decals.json", "storefront_strokes.json", "torus_strokes.json"}) {
    Scene s = load_scene(PLUMBAGO_SOURCE_DIR "/scenes/" + std::string(file));
    s.params.set("strokes.vis_step_px", 16.0);
    gpu::Renderer renderer(s);
    renderer.render();
    s.params.set("strokes.vis_step_px", 0.5);
    Frame lean;
    renderer.render_frame(lean);
    EXPECT_EQ(lean.readback_bytes, 0u) << file;
    const Image outgrown = renderer.color();
    const Image resized = renderer.render().color, fresh = gpu::Renderer(s).render().color;
    EXPECT_EQ(largest_difference(resized, fresh), 0.0f) << file;
    EXPECT_GT(largest_difference(outgrown, fresh), 0.1f) << file << ": the outgrown frame left strokes out";
  }
}

}  // namespace
}  // namespace plumbago
