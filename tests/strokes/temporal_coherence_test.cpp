// The temporal-coherence measures of stroke rendering (experiments/temporal_coherence,
// docs/conventions.md): strokes with known motion give known sliding, births, deaths and changes; a static
// camera gives none, and no stroke-layer score (nothing moved).
#include <gtest/gtest.h>

#include <cmath>

#include "experiments/shower_door/coherence.hpp"
#include "experiments/shower_door/surface_motion.hpp"
#include "experiments/temporal_coherence/measures.hpp"
#include "experiments/temporal_coherence/stroke_frames.hpp"

namespace plumbago {
namespace {

using namespace temporal_coherence;

constexpr int kWidth = 320, kHeight = 240;

Camera front_camera() {
  Camera c;
  c.eye = {0, 0, 5}, c.target = {0, 0, 0}, c.up = {0, 1, 0};
  return c;
}

// A stroke through the world points (x, y, 0), x from x0 to x1 in `count` samples, seen by
// `c`; its s is the window arc length from its first sample plus `s_shift`. Its path curve:
// a hash of its kind and y (one path per line).
TrackedRun stroke(const Camera& c, LineKind kind, double x0, double x1, double y, int count, double s_shift = 0) {
  WindowProjection project(c, kWidth, kHeight);
  TrackedRun run{kind, 0, std::hash<double>()(y) ^ uint64_t(kind), 0, false, {}};
  for (int k = 0; k < count; ++k) {
    glm::dvec3 world(std::lerp(x0, x1, double(k) / (count - 1)), y, 0), seen = project(world);
    double s = k == 0 ? 0 : run.length_px + glm::distance(glm::dvec2(seen), run.samples.back().window);
    run.length_px = s;
    run.samples.push_back({world, glm::dvec2(seen), seen.z, s, 4.0, 0.5, glm::dvec2(0), s});
  }
  for (TrackedSample& q : run.samples) q.s += s_shift;
  run.length_px += s_shift;
  return run;
}

// A frame of `runs` whose paths are theirs and `hidden`'s.
FrameStrokes frame(std::vector<TrackedRun> runs, const std::vector<TrackedRun>& hidden = {}) {
  FrameStrokes f{front_camera(), kWidth, kHeight, std::move(runs), {}};
  for (const TrackedRun& r : f.runs) f.curves.insert(r.curve);
  for (const TrackedRun& r : hidden) f.curves.insert(r.curve);
  return f;
}

// By value: the measures are often a temporary's.
PairMeasures of(const std::vector<std::pair<std::string, PairMeasures>>& all, const std::string& kind) {
  for (const auto& [name, m] : all)
    if (name == kind) return m;
  throw std::out_of_range("no kind " + kind);
}

TEST(TemporalCoherence, KnownShiftAlongTheStrokeIsItsSlide) {
  Camera c = front_camera();
  FrameStrokes prev = frame({stroke(c, LineKind::Crease, -1, 1, 0, 60)});
  FrameStrokes next = frame({stroke(c, LineKind::Crease, -1, 1, 0, 60, 5.0)});  // the stroke's start moved 5 px back
  next.runs[0].samples[10].alpha = 0.75, next.runs[0].samples[20].width = 5.5;
  next.runs[0].samples[30].offset = {0.6, -0.8};
  auto all = pair_measures(prev, next);
  ASSERT_EQ(all.size(), 2u);  // crease, all
  const PairMeasures& m = of(all, "crease");
  EXPECT_EQ(m.samples, 60u);
  EXPECT_EQ(m.matched, 60u);
  EXPECT_EQ(m.born + m.died, 0u);
  Stats slide = stats(m.slide_px);
  EXPECT_NEAR(slide.median, 5.0, 1e-9);
  EXPECT_NEAR(slide.max, 5.0, 1e-9);
  EXPECT_NEAR(stats(m.alpha_change).max, 0.25, 1e-9);
  EXPECT_NEAR(stats(m.width_change_px).max, 1.5, 1e-9);
  EXPECT_NEAR(stats(m.offset_change_px).max, 1.0, 1e-9);
  EXPECT_NEAR(stats(m.stretch).max, 0.0, 1e-9);  // under arc length, whatever its shift
  EXPECT_EQ(of(all, "all").matched, 60u);
}

// A texture parameter that runs 1.5 times as fast as arc length, or backwards at 0.5, is
// stretched by 0.5 everywhere.
TEST(TemporalCoherence, StretchIsTheParametersRateOffOne) {
  Camera c = front_camera();
  for (double rate : {1.5, -0.5}) {
    TrackedRun run = stroke(c, LineKind::Silhouette, -1, 1, 0, 30);
    for (TrackedSample& q : run.samples) q.s = 100 + rate * q.arc_px;
    PairMeasures m = of(pair_measures(frame({run}), frame({run})), "silhouette");
    ASSERT_EQ(m.stretch.size(), 29u);
    EXPECT_NEAR(stats(m.stretch).median, 0.5, 1e-9);
    EXPECT_NEAR(stats(m.stretch).max, 0.5, 1e-9);
  }
}

TEST(TemporalCoherence, LoopSlidesTheShorterWayAroundItsSeam) {
  Camera c = front_camera();
  TrackedRun a = stroke(c, LineKind::Silhouette, -1, 1, 0, 40), b = a;
  a.closed = b.closed = true;
  for (TrackedSample& q : b.samples) q.s = std::fmod(q.s + b.length_px - 7.0, b.length_px);  // seam 7 px on
  Stats slide = stats(of(pair_measures(frame({a}), frame({b})), "silhouette").slide_px);
  EXPECT_NEAR(slide.max, 7.0, 1e-9);
}

TEST(TemporalCoherence, UnmatchedStrokesAreBornOrDie) {
  Camera c = front_camera();
  TrackedRun kept = stroke(c, LineKind::Crease, -1, 1, 0, 30), gone = stroke(c, LineKind::Crease, -1, 1, 0.5, 30);
  TrackedRun fresh = stroke(c, LineKind::Border, -1, 1, -0.5, 30);
  TrackedRun other_kind = stroke(c, LineKind::Border, -1, 1, 0.5, 30);  // where `gone` was: not the same stroke
  auto all = pair_measures(frame({kept, gone}), frame({kept, fresh, other_kind}));
  EXPECT_EQ(of(all, "crease").died, 1u);
  EXPECT_EQ(of(all, "crease").died_px, gone.length_px);
  EXPECT_EQ(of(all, "border").born_px, fresh.length_px + other_kind.length_px);
  EXPECT_EQ(of(all, "crease").born, 0u);
  EXPECT_EQ(of(all, "border").born, 2u);
  EXPECT_EQ(of(all, "all").runs_next, 3u);
  EXPECT_EQ(of(all, "all").matched, 30u);
}

// A crease hidden in the next frame does not land on the crease beside it (its path is
// still there, hidden); a silhouette, whose path changes every frame, lands on the one
// beside it.
TEST(TemporalCoherence, FixedPathsLandOnlyOnThemselves) {
  Camera c = front_camera();
  for (LineKind kind : {LineKind::Crease, LineKind::Silhouette}) {
    TrackedRun a = stroke(c, kind, -1, 1, 0, 30), beside = stroke(c, kind, -1, 1, 0.002, 30);  // 0.2 px above
    std::vector<TrackedRun> hidden;
    if (kind == LineKind::Crease) hidden.push_back(a);
    PairMeasures m = of(pair_measures(frame({a}), frame({beside}, hidden)), line_kind_name(kind));
    EXPECT_EQ(m.matched, kind == LineKind::Crease ? 0u : 30u) << line_kind_name(kind);
  }
}

TEST(TemporalCoherence, AStrokeInFrontDoesNotCatchAHiddenOne) {
  Camera c = front_camera();
  TrackedRun behind = stroke(c, LineKind::Crease, -1, 1, 0, 30);
  TrackedRun in_front = behind;  // the same window line, halfway to the eye
  for (TrackedSample& q : in_front.samples) q.depth *= 0.5, q.world = glm::mix(glm::dvec3(c.eye), q.world, 0.5);
  EXPECT_EQ(of(pair_measures(frame({behind}), frame({in_front})), "crease").matched, 0u);
}

// The study's frames: a static camera gives the same strokes twice (no slide, no births or
// deaths, no change) and no moving pixel, so no stroke-layer score; a 2-degree turn of the
// torus carries nearly every silhouette sample onto the next frame's silhouettes.
TEST(TemporalCoherence, StaticCameraChangesNothingAndATurnIsFollowed) {
  std::string path = std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/torus_strokes.json";
  for (double step : {0.0, 2.0}) {
    Scene scene = study_scene(path, {}, step, 2);
    scene.width = kWidth, scene.height = kHeight;
    StrokeFrame a = render_stroke_frame(scene, 0), b = render_stroke_frame(scene, 1);
    PairMeasures m = of(pair_measures(a.strokes, b.strokes), "all");
    Image motion = shower_door::surface_motion(a.strokes.camera, a.points, b.points);
    double layer = shower_door::residuals(a.layer, b.layer, motion, shower_door::Sampling::Bilinear).coherence();
    std::printf(
        "[temporal coherence, torus %dx%d, %g deg] %zu of %zu samples matched, slide mean %.3f px, "
        "layer coherence %.3f\n",
        kWidth, kHeight, step, m.matched, m.samples, stats(m.slide_px).mean, layer);
    ASSERT_GT(m.samples, 100u);
    if (step == 0) {
      EXPECT_EQ(m.matched, m.samples);
      EXPECT_EQ(m.born + m.died, 0u);
      for (const auto& changes : {m.slide_px, m.alpha_change, m.width_change_px, m.offset_change_px})  // landed at a
        EXPECT_NEAR(stats(changes).max, 0.0, 1e-12);  // piece's end, t is 1 within rounding
      EXPECT_TRUE(std::isnan(layer));
    } else {
      EXPECT_GT(double(m.matched), 0.9 * double(m.samples));
      EXPECT_GT(layer, 0.0);
    }
  }
}

}  // namespace
}  // namespace plumbago
