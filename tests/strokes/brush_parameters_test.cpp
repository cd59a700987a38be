// Coherent silhouettes (Kalnins et al. 2003) as a stage of both renderers, under
// strokes.coherent (common/strokes/brush_parameters.hpp): along a camera path each frame's
// silhouette brush parameters come from the frame before; a frame that follows none draws the
// 2002 paper's arc length; frame k is the same drawn alone or in order; and the GPU renderer,
// which keeps its samples, votes and fit on the GPU, carries them as the reference does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "common/scene/animation.hpp"
#include "common/strokes/brush_parameters.hpp"
#include "common/util/image_compare.hpp"
#include "gpu/core/pipeline.hpp"
#include "gpu/core/stage.hpp"
#include "gpu/strokes/brush_parameters.hpp"
#include "parity/parity.hpp"
#include "parity/path_frames.hpp"
#include "reference/core/pipeline.hpp"
#include "tests/support/coherent_orbit.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

constexpr int kFrames = 4;

Scene coherent(Scene s, bool on) {
  s.params.set("strokes.coherent", on ? 1.0 : 0.0);
  return s;
}

// The torus orbit's silhouettes turn over the surface: their arc-length texture slides.
TEST(BrushParameters, FramesFollowTheFrameBeforeAndOnlyIt) {
  Scene on = coherent(testing::orbit_scene("torus_strokes.json", kFrames), true);
  Scene off = coherent(on, false);
  PathFrames in_order(on, "reference");
  std::vector<Image> drawn;
  for (int k = 0; k < kFrames; ++k) drawn.push_back(in_order.render(k).color);
  // The first frame follows none: arc length, as without the stage.
  EXPECT_EQ(drawn[0].data, PathFrames(off, "reference").render(0).color.data);
  // The last, asked for alone, draws the frames before it first.
  EXPECT_EQ(PathFrames(on, "reference").render(kFrames - 1).color.data, drawn.back().data);
  // Drawn alone by a renderer that draws nothing before it: arc length.
  Image alone = reference::render(scene_at_frame(on, kFrames - 1)).color;
  EXPECT_EQ(alone.data, reference::render(scene_at_frame(off, kFrames - 1)).color.data);
  ImageDiff moved = compare_images(drawn.back(), alone, tolerance::kByte);
  std::printf("torus orbit, frame %d: coherent against arc length: %s\n", kFrames - 1,
              format_diff("stroke.color", moved).c_str());
  EXPECT_GT(moved.over_tolerance * double(moved.compared), 100.0) << "the carried parameters changed no stroke";
}

// A reference brush sample and its arc length from its run's start (the t it would have
// without the carry).
struct Sampled {
  BrushSample sample;
  double s;
};

// The reference's frames along a path with their carry; per frame its brush samples.
std::vector<std::vector<Sampled>> reference_samples(const Scene& path) {
  std::vector<std::vector<Sampled>> out;
  Carry carry;
  for (int k = 0; k < kFrames; ++k) {
    std::vector<PassTime> ran;
    Scene at = scene_at_frame(path, k);
    reference::ReferenceFrame f = reference::run_stages(at, ran, carry.before(k));
    const std::vector<BrushSample>& carried = f.get(kBrushSamples);
    std::vector<BrushSample> arc =
        brush_samples(f.get(kWindowLines), f.get(kVisibleRuns), {}, at.params.get<CoherenceParams>(), at.seed);
    out.emplace_back();
    for (size_t i = 0; i < carried.size(); ++i) out.back().push_back({carried[i], arc.at(i).t});
    carry = {k, f.data};
  }
  return out;
}

class BrushParametersParity : public testing::GlTest {};

// Each backend finds its own visible runs (their ends within 1 px of each other: the
// visibility stage's tolerance), so samples are matched by place: each reference sample to
// the GPU's nearest in the window, of the same run where the runs match. A run end 1 px
// apart moves a sample by at most 2 px (its start and its spacing: s = L j / n) and its s,
// so its t, by at most 2 px; the reference's t and the GPU's are compared there.
// How the GPU renderer's brush samples along a path compare with the reference's.
struct Carried {
  size_t compared = 0, unmatched = 0, carried = 0;
  double worst_t = 0;
};

Carried carried_as_the_reference(const Scene& path) {
  std::vector<std::vector<Sampled>> ref = reference_samples(path);
  Scene at = scene_at_frame(path, 0);
  gpu::Renderer renderer(at);
  Carried c;
  for (int k = 0; k < kFrames; ++k) {
    if (k > 0) move_along_path(at, k), renderer.camera_moved();
    renderer.render();
    std::vector<BrushSample> gpu = renderer.frame().get(gpu::kGpuBrushSamples).samples();
    WindowProjection project(at.camera, at.width, at.height);
    for (const Sampled& r : ref[k]) {
      glm::dvec2 w(project(r.sample.world));
      const BrushSample* nearest = nullptr;
      double best = 2.0;
      for (const BrushSample& g : gpu) {
        double d = glm::distance(glm::dvec2(project(g.world)), w);
        if (d <= best) best = d, nearest = &g;
      }
      if (!nearest) {
        ++c.unmatched;
        continue;
      }
      c.worst_t = std::max(c.worst_t, std::abs(nearest->t - r.sample.t));
      c.carried += std::abs(r.sample.t - r.s) > 2.0;  // where arc length would fail the test
      ++c.compared;
    }
  }
  std::printf(
      "brush parameters, %d frames: %zu reference samples matched within 2 px (%zu unmatched, %zu whose t is 2 px or "
      "more off arc length), t within %.3g px\n",
      kFrames, c.compared, c.unmatched, c.carried, c.worst_t);
  EXPECT_GT(c.compared, 100u);
  EXPECT_GT(c.carried, 20u);
  EXPECT_LE(c.worst_t, 2.0);
  EXPECT_LE(c.unmatched, c.compared / 100);
  return c;
}

TEST_F(BrushParametersParity, TheGpuRendererCarriesAsTheReference) {
  for (const char* name : testing::kOrbitScenes) {
    std::printf("%s orbit: ", name);
    carried_as_the_reference(coherent(testing::orbit_scene(name, kFrames), true));
  }
}

// Both renderers read the scene's coherence.* parameters: with every one away from its
// default, the GPU still carries as the reference does, and the reference's samples are
// another set than the defaults give (the parameters reached it).
TEST_F(BrushParametersParity, BothRenderersReadTheCoherenceParameters) {
  Scene path = coherent(testing::orbit_scene("torus_strokes.json", kFrames), true);
  for (const std::string& set : testing::kCoherenceSets) path.params.set_assignment(set);
  std::printf("torus orbit, every coherence parameter set: ");
  carried_as_the_reference(path);
  Scene defaults = coherent(testing::orbit_scene("torus_strokes.json", kFrames), true);
  EXPECT_NE(reference_samples(path).back().size(), reference_samples(defaults).back().size());
}

// The GPU's carry reads nothing back: a frame that follows one votes, fits and samples on the
// GPU, and reads back what the same frame without it does (the counts the first frame after
// a camera move sizes its buffers by), its pass timed with the rest.
Frame following_frame(bool on) {
  Scene at = scene_at_frame(coherent(testing::orbit_scene("torus_strokes.json", 2), on), 0);
  gpu::Renderer renderer(at);
  renderer.render();
  move_along_path(at, 1), renderer.camera_moved();
  Frame timing;
  renderer.render_frame(timing);
  return timing;
}

TEST_F(BrushParametersParity, AFrameThatFollowsReadsNothingMoreBack) {
  Frame on = following_frame(true), off = following_frame(false);
  EXPECT_EQ(on.readback_bytes, off.readback_bytes);
  auto ran = std::find_if(on.ran.begin(), on.ran.end(), [](const PassTime& p) { return p.name == "brush_parameters"; });
  ASSERT_NE(ran, on.ran.end());
  std::printf("torus, a frame that follows: brush_parameters %.3f ms (GPU timer), %zu bytes read back (%zu without)\n",
              ran->ms, on.readback_bytes, off.readback_bytes);
}

// The viewer's renderer (every frame follows the one before it) carries along views that are
// no path's frames as a renderer along the path does: the same samples, t bit for bit. A
// renderer whose frames follow only their path's next one draws those views (each frame 0 of
// a path) at arc length.
TEST_F(BrushParametersParity, ARendererWhoseEveryFrameFollowsCarriesAlongFreeViews) {
  Scene path = coherent(testing::orbit_scene("torus_strokes.json", kFrames), true);
  Scene at = scene_at_frame(path, 0), free = at, first = at;
  free.animation.reset();  // views of no path: frame 0 each
  gpu::Renderer along(at), viewer(free), alone(first);
  viewer.follow_every_frame();
  size_t samples = 0, off_arc_length = 0;
  for (int k = 0; k < kFrames; ++k) {
    if (k > 0) {
      move_along_path(at, k), along.camera_moved();
      take_view(free, at), free.frame = 0, free.path_start = free.camera;
      take_view(first, at), first.frame = 0, first.path_start = first.camera;
      viewer.camera_moved(), alone.camera_moved();
    }
    along.render(), viewer.render(), alone.render();
    const auto brushed = [](const gpu::Renderer& r) { return r.frame().get(gpu::kGpuBrushSamples).samples(); };
    std::vector<BrushSample> want = brushed(along), got = brushed(viewer), arc = brushed(alone);
    ASSERT_EQ(got.size(), want.size()) << "frame " << k;
    ASSERT_EQ(arc.size(), want.size()) << "frame " << k;
    for (size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(got[i].t, want[i].t) << "frame " << k << " sample " << i;
      EXPECT_EQ(got[i].world, want[i].world) << "frame " << k << " sample " << i;
      off_arc_length += std::abs(arc[i].t - want[i].t) > 2.0;
    }
    samples += want.size();
  }
  std::printf("torus orbit as free views, every frame following: %zu samples as along the path (%zu off arc length)\n",
              samples, off_arc_length);
  EXPECT_GT(off_arc_length, 20u) << "the views did not carry";
}

// A still scene (no camera path) outside the viewer: no frame follows another, so the GPU's
// stage does no work (no fit, no samples) and the strokes are drawn at arc length, as with
// strokes.coherent off, pixel for pixel.
TEST_F(BrushParametersParity, AStillSceneDoesNoCoherenceWork) {
  Scene still = scene_at_frame(coherent(testing::orbit_scene("torus_strokes.json", kFrames), true), 1);
  still.animation.reset();
  Scene off = coherent(still, false);
  gpu::Renderer on_renderer(still), off_renderer(off);
  for (int k = 0; k < 2; ++k) {  // the second frame too: it follows none either
    Image on = on_renderer.render().color, drawn_off = off_renderer.render().color;
    EXPECT_EQ(on.data, drawn_off.data) << "frame " << k;
    EXPECT_EQ(on_renderer.frame().get(maybe(gpu::kGpuBrushSamples)), nullptr) << "frame " << k;
    EXPECT_EQ(on_renderer.frame().get(maybe(gpu::kBrushFit)), nullptr) << "frame " << k;
  }
}

// Markov-synthesized silhouettes on loops longer than a brush path's period (the torus's,
// 1024 px): with strokes.coherent on, each backend draws every silhouette's brush path
// (common/strokes/coherent_silhouettes.hpp 5.; new ones in a frame that follows none),
// whether the stroke stage is fed alone (the parity harness, which feeds no brush
// parameters) or runs in a whole frame; the periodic walk differs from the run's own past
// its period, so a backend that took the run's own would not agree.
TEST_F(BrushParametersParity, SynthesizedSilhouettesDrawTheirBrushPathsOnBothBackends) {
  Scene scene = scene_at_frame(coherent(testing::orbit_scene("torus_strokes.json", kFrames), true), 1);
  scene.animation.reset();
  scene.strokes.silhouette = load_stroke_style("sketchy_pencil");
  ASSERT_EQ(scene.strokes.silhouette.synthesis, OffsetSynthesis::Markov);
  for (const StageParity& r : run_parity(scene, {"stroke"})) {
    std::printf("%s: max %.3g, %.4f%% over %.3g\n", r.name.c_str(), r.diff.max_abs, 100 * r.diff.over_tolerance,
                r.diff.tolerance);
    EXPECT_TRUE(r.pass) << r.name;
  }
  Image gpu = gpu::Renderer(scene).render().color;
  Image reference = reference::render(scene).color;
  ImageDiff whole = compare_images(reference, gpu, tolerance::kByte);
  std::printf("whole frame, GPU against reference: max %.3g, %.4f%% of pixels over %.3g\n", whole.max_abs,
              100 * whole.over_tolerance, tolerance::kByte);
  EXPECT_LT(whole.over_tolerance, 1e-4);
  Image off = gpu::Renderer(coherent(scene, false)).render().color;
  EXPECT_GT(compare_images(off, gpu, tolerance::kByte).over_tolerance, 1e-4) << "past the period the two walks differ";
}

}  // namespace
}  // namespace plumbago
