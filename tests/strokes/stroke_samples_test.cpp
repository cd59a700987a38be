// The GPU's stroke samples (shaders/strokes/stroke_samples.comp, in double) against the
// reference's (common/strokes/base_stroke.hpp 1.-5., in double), sample by sample, as the
// ribbons read them (gpu/strokes/stroke.hpp SampleRecord, in float): on the hard cases of a
// base stroke and on every visible run of the procedural stroke scenes. Both compute the same
// formulas in double in the same order, but for a few library calls (std::pow and std::lerp
// against sqrt and mix) and GLSL's double division, which need not be correctly rounded: they
// differ by a few units of double rounding, so the counts, pen flags and runs must agree
// exactly, and each float output within one float rounding. (Where a formula jumps, at a
// rubber stamp's period, a few units of rounding decide the side: an example made for its
// run, whose end lies at its period, does not repeat, OffsetExample::repeats.)
// Through a frame's way, the runs' polylines and styles are made on the GPU too
// (shaders/strokes/run_inputs.comp) from the run tables of gpu/strokes/window_paths.hpp and the
// style tables of gpu/strokes/run_styles.hpp, against the reference's run_along and RunStyles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "common/scene/animation.hpp"
#include "common/scene/scene.hpp"
#include "gpu/strokes/brush_fit.hpp"
#include "gpu/strokes/brush_votes.hpp"
#include "gpu/strokes/stroke_samples.hpp"
#include "parity/lines.hpp"
#include "tests/support/coherent_orbit.hpp"
#include "tests/support/stroke_cases.hpp"
#include "tests/support/test_scenes.hpp"

namespace plumbago {
namespace {

// a and b are one float rounding of two doubles a few double roundings apart at most: within
// one unit in the last place of the larger of them and `scale`, the quantity's own size
// (alpha's is 1: a factor of (1 - x^2) near x = 1 is 0 in one and 1e-16 in the other).
bool within_one_ulp(float a, float b, float scale = 0) {
  float larger = std::max({std::abs(a), std::abs(b), scale});
  return std::abs(a - b) <= std::nextafter(larger, std::numeric_limits<float>::infinity()) - larger;
}

struct Tally {
  size_t samples = 0, runs = 0, differing = 0;
};

// Every run of `runs`: the GPU's records against the reference's samples.
Tally compare(const std::vector<StyledRun>& runs, const gpu::StrokeSamples& gpu_samples) {
  std::vector<gpu::SampleRecord> samples = gpu_samples.samples();
  std::vector<gpu::RunRecord> records = gpu_samples.runs();
  Tally t;
  for (size_t r = 0; r < runs.size(); ++r) {
    const StrokeStyle& style = runs[r].style;
    BaseStrokeSamples ref = base_stroke_samples(runs[r].run, style);
    const std::vector<StrokeSample>& q = ref.samples;
    const gpu::RunRecord& g = records.at(r);
    EXPECT_LE(double(q.size()), gpu::sample_bound(runs[r])) << "run " << r << ": the buffers' bound is not one";
    EXPECT_EQ(g.count, q.size()) << "run " << r;
    if (g.count != q.size()) continue;
    bool whole =
        std::all_of(q.begin(), q.end() - (q.empty() ? 0 : 1), [](const StrokeSample& x) { return x.pen_down_after; });
    EXPECT_EQ(g.cyclic != 0, ref.closed && whole) << "run " << r;
    EXPECT_EQ(g.color_layer, glm::vec4(style.color_r, style.color_g, style.color_b, float(int(style.texture))));
    t.runs += q.empty() ? 0 : 1;
    for (size_t j = 0; j < q.size(); ++j) {
      const gpu::SampleRecord& s = samples.at(g.first + j);
      glm::vec2 p(q[j].position);
      float u = float(q[j].t / style.texture_period_px), w = float(q[j].width), a = float(q[j].alpha);
      bool same = s.position == p && s.u == u && s.width == w && s.alpha == a;
      t.differing += same ? 0 : 1;
      EXPECT_TRUE(within_one_ulp(s.position.x, p.x) && within_one_ulp(s.position.y, p.y))
          << "run " << r << " sample " << j << ": (" << s.position.x << ", " << s.position.y << ") against (" << p.x
          << ", " << p.y << ")";
      EXPECT_TRUE(within_one_ulp(s.u, u) && within_one_ulp(s.width, w) && within_one_ulp(s.alpha, a, 1.0f))
          << "run " << r << " sample " << j;
      EXPECT_EQ(s.pen_down_after != 0, q[j].pen_down_after) << "run " << r << " sample " << j;
      EXPECT_EQ(s.run, r);
    }
    t.samples += q.size();
  }
  return t;
}

// The runs given by their polylines.
Tally compare(const std::vector<StyledRun>& runs) {
  gpu::StrokeSamples gpu_samples;
  gpu_samples(runs);
  return compare(runs, gpu_samples);
}

// The visible runs of `found` as a frame gives them: their paths and runs on the GPU, each
// run's polyline and style made there (against the reference's run_along and RunStyles).
Tally compare_from_tables(const SceneLines& found) {
  const WindowLines& lines = found.lines;
  const Visibility& v = found.visibility;
  gpu::UploadedRuns tables(lines, v);
  gpu::RunStyleTables styles(found.scene.strokes, lines.decal_styles);
  gpu::StrokeSamples gpu_samples;
  gpu_samples(tables.tables(), styles, found.scene.seed);
  return compare(styled_runs(lines, v, found.scene.strokes, found.scene.seed), gpu_samples);
}

StrokeStyle style(double width) { return testing::style_of_width(width); }

using testing::arc;

// A run through `p` in style `s`.
struct Cases {
  std::vector<StyledRun> runs;
  void add(std::vector<glm::dvec2> p, bool closed, const StrokeStyle& s, bool occluded_start = false,
           bool occluded_end = false, BrushParameter brush = {}) {
    StyledRun r;
    r.run.points = std::move(p);
    r.run.brush = std::move(brush);
    r.run.closed = closed, r.run.occluded_start = occluded_start, r.run.occluded_end = occluded_end;
    r.style = s;
    runs.push_back(std::move(r));
  }
};

std::vector<StyledRun> hard_cases() {
  Cases c;
  StrokeStyle tapered = style(9);
  tapered.taper_px = 30, tapered.halo_px = 15, tapered.fade_px = 10, tapered.flare = 0.5f;
  std::vector<glm::dvec2> wave;
  for (int i = 0; i <= 40; ++i) wave.push_back({20.0 + 8 * i, 300 + 40 * std::sin(i * 0.4)});
  c.add(wave, false, tapered, true);                  // open: taper, fade, flare, halo at its start
  c.add(wave, false, tapered, true, true);            // haloed at both ends
  c.add(arc({200, 200}, 60, 36, 1), true, style(6));  // closed, drawn whole
  StrokeStyle lifted = style(5);
  lifted.offsets = OffsetExample{70, {{0, 0, 1, false}, {0.4, 2, 0.7, true}, {0.6, -1, 1, false}}};
  lifted.pressure_alpha = true;
  c.add(arc({420, 180}, 50, 30, 1), true, lifted);  // closed, split by pen lifts
  c.add(wave, false, lifted);                       // open, many periods
  StrokeStyle zigzag = style(1.5);                  // thin: drawn 2 px wide
  zigzag.sample_px = 2;
  zigzag.offsets = OffsetExample{5, {{0, 1.5, 1, false}, {0.5, -1.5, 1, false}}};
  c.add({{30, 500}, {300, 520}, {560, 480}}, false, zigzag);  // offsets faster than the spacing
  // Pen changes near even samples and ends: lifts over t in (0.3, 0.6) and (0.999, 1) of a 10
  // px example give changes at 3, 6, 9.99, 10, 13, 16, 19.99 and 20 px. A straight run 21.315 px
  // long sampled every 3.1 px has even samples 3.045 px apart: the first 0.045 px from the
  // change at 3, which it gives way to. On one 20.045 px long the change at 20 lies 0.045 px
  // from the end and gives way to it.
  StrokeStyle near = style(4);
  near.sample_px = 3.1f;
  near.offsets = OffsetExample{10, {{0, 0, 1, false}, {0.3, 0, 1, true}, {0.6, 0, 1, false}, {0.999, 0, 1, true}}};
  c.add({{100, 50}, {121.315, 50}}, false, near);
  c.add({{100, 60}, {120.045, 60}}, false, near);
  StrokeStyle made = style(4);  // an example made for its run, which is longer: held, its last lift too
  made.offsets = OffsetExample{60, {{0, 1, 1, false}, {0.5, -1, 0.6, false}, {0.8, 2, 1, true}}, false};
  c.add({{100, 200}, {140, 215}, {175, 200}}, false, made);
  StrokeStyle late = style(4);  // the first offset after t = 0: the stretch before it wraps from the last
  late.offsets = OffsetExample{25, {{0.2, 1.5, 1, false}, {0.7, -1.5, 0.5, false}}};
  c.add({{100, 120}, {180, 135}, {260, 120}}, false, late);
  double nan = std::numeric_limits<double>::quiet_NaN();  // dropped, as are repeats within 1e-6 px
  c.add({{10, 10}, {10, 10}, {nan, 5}, {30, 12}, {30, 12 + 1e-7}, {50, 10}, {50, 10}}, false, style(4));
  c.add({{60, 60}, {90, 70}, {60, 60}}, true, style(4));                // closed, two distinct points: drawn open
  c.add({{200, 90}, {230, 95}, {260, 90}, {200, 90}}, true, style(4));  // its last point its first
  c.add({{70, 70}, {70, 70}}, false, style(4));                         // one distinct point: nothing
  c.add({{10, 300}, {10.5, 300}, {10, 300}}, false, style(4));          // there and back in one step: nothing
  c.add(arc({3800, 2900}, 25, 20, 0.7), false, style(7));               // far from the origin
  // Brush parameters (Kalnins et al. 2003): the texture and a repeating example's offsets and
  // lifts follow t; an example made for its run stays on s.
  c.add(wave, false, lifted, false, false, {{0, 37}, {100, 137}});                           // shifted, extended
  c.add(wave, false, lifted, false, false, {{0, 500}, {100, 400}, {100, 40}, {400, -260}});  // reversed, a jump
  c.add(wave, false, lifted, false, false, {{0, 0}, {60, 80}, {120, 120}, {200, 250}});      // stretched unevenly
  c.add(arc({420, 380}, 50, 30, 1), true, lifted, false, false, {{0, 10}, {150, 170}, {300, 300}});  // a loop
  c.add({{100, 200}, {140, 215}, {175, 200}}, false, made, false, false, {{0, 20}, {50, 80}});
  c.add(wave, false, lifted, false, false, {{30, 7}});  // one knot: t = s
  return c.runs;
}

class StrokeSamplesParity : public testing::GlTest {};

// Coherent silhouettes (Kalnins et al. 2003) all on the GPU: along an orbit, the last frame's
// brush samples vote over this frame's runs, the votes are fitted, and the stroke samples
// take each run's knots from the fit (shaders/strokes/run_knots.comp): sample by sample as
// the reference draws the runs with the parameters coherent_parameters gives them.
TEST_F(StrokeSamplesParity, CoherentParametersFittedOnTheGpuDrawAsTheReference) {
  for (const char* name : testing::kOrbitScenes) {
    Tally t;
    size_t brushed = 0;
    testing::follow_coherent_orbit(name, 3, [&](const testing::CoherentFrame& f) {
      std::vector<StyledRun> runs =
          styled_runs(f.found.lines, f.found.visibility, f.at.strokes, f.at.seed, f.reference);
      for (const RunBrush& b : f.reference) brushed += b.knots.size() >= 2;
      gpu::RunStyleTables styles(f.at.strokes, f.found.lines.decal_styles);
      gpu::StrokeSamples gpu_samples;
      gpu_samples(f.tables, styles, f.at.seed, &f.fit);
      Tally frame_tally = compare(runs, gpu_samples);
      t.samples += frame_tally.samples, t.runs += frame_tally.runs, t.differing += frame_tally.differing;
    });
    EXPECT_GT(brushed, 2u) << name;
    std::printf(
        "stroke samples, %s, coherent: %zu samples in %zu runs (%zu with a fitted parameter), %zu not "
        "bit-equal (within one float ulp)\n",
        name, t.samples, t.runs, brushed, t.differing);
  }
}

TEST_F(StrokeSamplesParity, HardCasesMatchTheReference) {
  Tally t = compare(hard_cases());
  EXPECT_GT(t.samples, 300u);
  std::printf("stroke samples, hard cases: %zu samples in %zu runs, %zu not bit-equal (within one float ulp)\n",
              t.samples, t.runs, t.differing);
}

// The procedural stroke scenes' visible runs, in their styles, as a frame gives them (their
// polylines made on the GPU from their paths): rubber-stamped and synthesized
// offsets (the snowman's and the storefront's Markov chains), decals and hatches with their
// drawn pressure (hatching_lod), plain silhouettes (the torus).
class StrokeSamplesScenes : public testing::GlTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(StrokeSamplesScenes, EveryVisibleRunMatchesTheReference) {
  Scene scene = load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/" + GetParam());
  SceneLines found = scene_lines(scene, "reference");
  ASSERT_FALSE(found.visibility.runs.empty());
  size_t past_seam = 0, whole_loops = 0;  // the hard polylines: a closed path's run over its seam, or all of it
  for (const VisibleRun& r : found.visibility.runs) {
    past_seam += r.s1 > found.lines.paths[r.path].length_px;
    whole_loops += r.closed;
  }
  Tally t = compare_from_tables(found);
  std::printf(
      "stroke samples, %s: %zu samples in %zu runs (%zu past a seam, %zu whole loops), %zu not bit-equal "
      "(within one float ulp)\n",
      GetParam(), t.samples, t.runs, past_seam, whole_loops, t.differing);
}

// Every way a line kind's runs get their offsets (common/strokes/stroke.hpp RunOffsets) made on
// the GPU: the storefront's two drawn crease examples stamped in turn (Drawn) and synthesized
// (its own), the snowman's silhouette example stamped (Own) and synthesized, a plain style
// (None); the hatches' and decals' pressure comes with hatching_lod above.
TEST_F(StrokeSamplesParity, EachWayOfMakingOffsetsMatchesTheReference) {
  std::set<RunOffsets> ways;
  for (auto synthesis : {OffsetSynthesis::Stamp, OffsetSynthesis::Markov}) {
    for (const char* name : {"storefront_strokes.json", "snowman_strokes.json"}) {
      Scene scene = load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/" + name);
      for (StrokeStyle* style : {&scene.strokes.crease, &scene.strokes.border, &scene.strokes.silhouette})
        style->synthesis = synthesis;
      for (LineKind kind : {LineKind::Crease, LineKind::Border, LineKind::Silhouette})
        ways.insert(run_offsets(kind, scene.strokes));
      Tally t = compare_from_tables(scene_lines(scene, "reference"));
      std::printf("stroke samples, %s, %s: %zu samples in %zu runs, %zu not bit-equal\n", name,
                  synthesis == OffsetSynthesis::Stamp ? "stamped" : "synthesized", t.samples, t.runs, t.differing);
      EXPECT_GT(t.runs, 10u);
    }
  }
  EXPECT_EQ(ways.size(), 4u);
}

// Hatches made on the GPU as the dolly of hatching_lod passes their levels of detail (their
// alpha and width scaled), with a drawn pressure that varies along each and drives both: the
// pressure at a run's ends comes from between two drawn points.
TEST_F(StrokeSamplesParity, HatchesThroughTheirLevelsOfDetailMatchTheReference) {
  Scene study = load_scene(std::string(PLUMBAGO_SOURCE_DIR) + "/scenes/hatching_lod.json");
  for (StrokeFile& file : study.stroke_files)
    for (DrawnStroke& stroke : file.strokes) {
      for (size_t k = 0; k < stroke.points.size(); ++k) stroke.points[k].pressure = 0.2 + 0.08 * double(k * 37 % 11);
      if (stroke.style) stroke.style->pressure_width = stroke.style->pressure_alpha = true;
    }
  size_t scaled = 0, cut = 0;  // paths at a level between two, runs ending inside a path
  for (int frame : {0, 15, 30, 45, 59}) {
    SceneLines found = scene_lines(scene_at_frame(study, frame), "reference");
    for (const WindowPath& p : found.lines.paths) scaled += p.kind == LineKind::Hatching && p.width_scale != 1.0;
    for (const VisibleRun& r : found.visibility.runs)
      cut += found.lines.paths[r.path].kind == LineKind::Hatching && (r.occluded_start || r.occluded_end);
    Tally t = compare_from_tables(found);
    std::printf("stroke samples, hatching_lod frame %d: %zu samples in %zu runs, %zu not bit-equal\n", frame, t.samples,
                t.runs, t.differing);
  }
  std::printf("%zu hatch paths scaled by their level of detail, %zu hatch runs cut by occlusion\n", scaled, cut);
  EXPECT_GT(scaled, 0u);
  EXPECT_GT(cut, 0u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, StrokeSamplesScenes,
                         ::testing::Values("torus_strokes.json", "snowman_strokes.json", "storefront_strokes.json",
                                           "hatching_lod.json"),
                         [](const auto& info) {
                           std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace plumbago
