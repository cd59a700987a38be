// The GPU's votes of coherent silhouettes (shaders/strokes/brush_votes.comp) against the
// reference's brush_votes (common/strokes/coherent_silhouettes.hpp 2.): the last frame's
// brush samples of the procedural scenes' silhouettes, projected into the next frame of an
// orbit, vote for the same runs, in the same order, carrying the same t and stroke, at the
// same s within 1e-6 px (the same double formulas; the pieces' depths come from the path's
// points on the GPU and from its world points on the reference, which agree to rounding,
// far inside the depth test's 1%).
#include <gtest/gtest.h>

#include <cstdio>

#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "gpu/strokes/brush_fit.hpp"
#include "gpu/strokes/brush_votes.hpp"
#include "parity/lines.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

class BrushVotesParity : public testing::GlTest {};

TEST_F(BrushVotesParity, OrbitSamplesVoteAsTheReference) {
  for (const char* name : testing::kOrbitScenes) {
    Scene scene = testing::orbit_scene(name, 3);
    CoherenceParams p = ParamSet{}.get<CoherenceParams>();
    std::vector<BrushSample> previous;
    std::vector<RunBrush> fitted;
    size_t votes = 0;
    double worst = 0;
    gpu::BrushVotes gpu_votes;
    for (int frame = 0; frame < 3; ++frame) {
      Scene at = scene_at_frame(scene, frame);
      SceneLines found = scene_lines(at, "reference");
      if (frame > 0) {
        std::vector<BrushVote> ref = brush_votes(previous, at.camera, found.lines, found.visibility, p);
        gpu::UploadedRuns tables(found.lines, found.visibility);
        gpu_votes(previous, at.camera, at.width, at.height, tables.tables(), p);
        std::vector<BrushVote> gpu = gpu_votes.votes();
        ASSERT_EQ(gpu.size(), ref.size()) << name << " frame " << frame;
        for (size_t i = 0; i < ref.size(); ++i) {
          EXPECT_EQ(gpu[i].run, ref[i].run) << name << " vote " << i;
          EXPECT_EQ(gpu[i].t, ref[i].t) << name << " vote " << i;
          EXPECT_EQ(gpu[i].stroke, ref[i].stroke) << name << " vote " << i;
          EXPECT_EQ(gpu[i].path, ref[i].path) << name << " vote " << i;
          EXPECT_NEAR(gpu[i].s, ref[i].s, 1e-6) << name << " vote " << i;
          worst = std::max(worst, std::abs(gpu[i].s - ref[i].s));
        }
        votes += ref.size();
        fitted = coherent_parameters(previous, at.camera, found.lines, found.visibility, p);
      }
      previous = brush_samples(found.lines, found.visibility, fitted, p, at.seed);
    }
    EXPECT_GT(votes, 20u) << name;
    std::printf("brush votes, %s orbit: %zu votes, s within %.3g px\n", name, votes, worst);
  }
}

// Nothing through the CPU: the samples the GPU left last frame (their count on the GPU, one
// slot each its buffer holds) vote as the same samples read back and given, and the GPU's fit
// of those votes samples as the same knots read back and given.
TEST_F(BrushVotesParity, SamplesLeftOnTheGpuVoteAsThoseReadBack) {
  for (const char* name : testing::kOrbitScenes) {
    Scene scene = testing::orbit_scene(name, 3);
    CoherenceParams p = ParamSet{}.get<CoherenceParams>();
    gpu::BrushSamples left, given;
    gpu::BrushVotes from_gpu, from_cpu;
    gpu::BrushFit fit;
    size_t votes = 0, samples = 0;
    for (int frame = 0; frame < 3; ++frame) {
      Scene at = scene_at_frame(scene, frame);
      SceneLines found = scene_lines(at, "reference");
      gpu::UploadedRuns tables(found.lines, found.visibility);
      from_cpu(left.samples(), at.camera, at.width, at.height, tables.tables(), p);
      from_gpu(left, at.camera, at.width, at.height, tables.tables(), p);
      std::vector<BrushVote> cpu = from_cpu.votes(), gpu = from_gpu.votes();
      ASSERT_EQ(gpu.size(), cpu.size()) << name << " frame " << frame;
      EXPECT_GE(from_gpu.slots(), from_cpu.slots()) << name;
      for (size_t i = 0; i < cpu.size(); ++i) {
        EXPECT_EQ(gpu[i].run, cpu[i].run) << name << " vote " << i;
        EXPECT_EQ(gpu[i].s, cpu[i].s) << name << " vote " << i;
        EXPECT_EQ(gpu[i].t, cpu[i].t) << name << " vote " << i;
        EXPECT_EQ(gpu[i].path, cpu[i].path) << name << " vote " << i;
      }
      votes += cpu.size();
      fit(from_gpu, tables.tables(), p);
      left(tables.tables(), at.camera, at.width, at.height, &fit, p, at.seed);
      given(tables.tables(), at.camera, at.width, at.height, fit.parameters(), p, at.seed);
      std::vector<BrushSample> a = left.samples(), b = given.samples();
      ASSERT_EQ(a.size(), b.size()) << name << " frame " << frame;
      for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].t, b[i].t) << name << " sample " << i;
        EXPECT_EQ(a[i].world, b[i].world) << name << " sample " << i;
        EXPECT_EQ(a[i].path, b[i].path) << name << " sample " << i;
      }
      samples += a.size();
    }
    EXPECT_GT(votes, 20u) << name;
    std::printf("brush votes, %s orbit, samples left on the GPU: %zu votes and %zu samples as those read back\n", name,
                votes, samples);
  }
}

// A frame with no lines at all (the mesh left the view) after one with samples: no votes.
TEST_F(BrushVotesParity, AFrameWithoutRunsHasNoVotes) {
  Scene scene = testing::orbit_scene(testing::kOrbitScenes[0], 2);
  CoherenceParams p = ParamSet{}.get<CoherenceParams>();
  SceneLines found = scene_lines(scene, "reference");
  std::vector<BrushSample> previous = brush_samples(found.lines, found.visibility, {}, p, scene.seed);
  ASSERT_FALSE(previous.empty());
  gpu::BrushVotes votes;
  votes(previous, scene.camera, scene.width, scene.height, gpu::RunTables{}, p);
  EXPECT_TRUE(votes.votes().empty());
  EXPECT_EQ(votes.slots(), 0u);
}

}  // namespace
}  // namespace plumbago
