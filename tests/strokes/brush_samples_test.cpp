// The GPU's brush samples of coherent silhouettes (shaders/strokes/brush_samples.comp)
// against the reference's brush_samples (common/strokes/coherent_silhouettes.hpp 1.): the
// visible silhouette runs of the procedural scenes, with no parameter (t = s) and with the
// parameters fitted from the last frame's votes along an orbit: the same samples in the same
// order, the same t and runs, and the world points within 1e-9 of the scene's size (the GPU
// unprojects the window point at its depth, the reference interpolates the path's world
// points perspective-correctly: the same point, rounded apart).
#include <gtest/gtest.h>

#include <cstdio>

#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "gpu/strokes/brush_samples.hpp"
#include "parity/lines.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

class BrushSamplesParity : public testing::GlTest {};

TEST_F(BrushSamplesParity, SilhouetteRunsSampleAsTheReference) {
  for (const char* name : testing::kOrbitScenes) {
    Scene scene = testing::orbit_scene(name, 2);
    CoherenceParams p = ParamSet{}.get<CoherenceParams>();
    std::vector<BrushSample> previous;
    size_t compared = 0;
    double worst = 0, size = 0;
    gpu::BrushSamples gpu_samples;
    for (int frame = 0; frame < 2; ++frame) {
      Scene at = scene_at_frame(scene, frame);
      SceneLines found = scene_lines(at, "reference");
      std::vector<RunBrush> fitted(found.visibility.runs.size());
      if (frame > 0) fitted = coherent_parameters(previous, at.camera, found.lines, found.visibility, p);
      std::vector<BrushSample> ref = brush_samples(found.lines, found.visibility, fitted, p, at.seed);
      gpu::UploadedRuns tables(found.lines, found.visibility);
      gpu_samples(tables.tables(), at.camera, at.width, at.height, fitted, p, at.seed);
      std::vector<BrushSample> gpu = gpu_samples.samples();
      ASSERT_EQ(gpu.size(), ref.size()) << name << " frame " << frame;
      for (const BrushSample& b : ref) size = std::max(size, glm::length(b.world));
      for (size_t i = 0; i < ref.size(); ++i) {
        EXPECT_EQ(gpu[i].stroke, ref[i].stroke) << name << " sample " << i;
        EXPECT_EQ(gpu[i].path, ref[i].path) << name << " sample " << i;
        EXPECT_EQ(gpu[i].t, ref[i].t) << name << " sample " << i;
        double d = glm::distance(gpu[i].world, ref[i].world);
        EXPECT_LE(d, 1e-9 * std::max(size, 1.0)) << name << " sample " << i;
        worst = std::max(worst, d);
      }
      compared += ref.size();
      previous = std::move(ref);
    }
    EXPECT_GT(compared, 50u) << name;
    std::printf("brush samples, %s: %zu samples, world points within %.3g (scene size %.3g)\n", name, compared, worst,
                size);
  }
}

}  // namespace
}  // namespace plumbago
