// Coherent stylized silhouettes (Kalnins et al. 2003, common/strokes/coherent_silhouettes.hpp):
// the fit recovers a parameter the votes carry, in either direction and beyond the votes,
// weighs coherence against uniformity, gives each group of votes its section of the run;
// a run draws its texture
// at the parameter; and along an orbit of the torus, whose closed silhouettes' seams drift
// under the 2002 paper's arc length, the propagated parameter stays on the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common/strokes/coherent_silhouettes.hpp"
#include "common/strokes/offset_synthesis.hpp"
#include "experiments/temporal_coherence/measures.hpp"
#include "experiments/temporal_coherence/stroke_frames.hpp"

namespace plumbago {
namespace {

const CoherenceParams kDefaults = ParamSet{}.get<CoherenceParams>();

// Votes of `stroke` every sample_px from s0 to s1 (as the last frame's samples land), carrying
// t(s) and the stroke's brush path, 100 + stroke.
template <class F>
std::vector<BrushVote> votes(double s0, double s1, F t, uint32_t stroke = 0) {
  std::vector<BrushVote> out;
  for (double s = s0; s <= s1; s += kDefaults.sample_px) out.push_back({0, s, t(s), stroke, 100 + stroke});
  return out;
}

// The largest departure of the fitted t from `want` over the run, every px.
template <class F>
double worst(const BrushParameter& knots, double length, F want) {
  double e = 0;
  for (double s = 0; s <= length; s += 1) e = std::max(e, std::abs(brush_t(knots, s) - want(s)));
  return e;
}

TEST(CoherentSilhouettes, FitCarriesAShiftedParameterOverTheWholeRun) {
  auto shifted = [](double s) { return s + 37.0; };
  RunBrush brush = fit_brush_parameter(votes(100, 200, shifted), 300, kDefaults);
  ASSERT_GE(brush.knots.size(), 2u);
  EXPECT_LT(worst(brush.knots, 300, shifted), 1e-6);  // beyond the votes too: uniformity runs on at rate 1
  EXPECT_EQ(brush.path, 100u);                        // the brush path its votes drew (5.)
}

TEST(CoherentSilhouettes, FitFollowsAPathTracedTheOtherWay) {
  auto reversed = [](double s) { return 500.0 - s; };
  EXPECT_LT(worst(fit_brush_parameter(votes(0, 240, reversed), 240, kDefaults).knots, 240, reversed), 1e-6);
}

TEST(CoherentSilhouettes, UniformityPullsAStretchedParameterTowardsRateOne) {
  auto stretched = [](double s) { return 1.5 * s; };
  CoherenceParams free = kDefaults;
  free.scale_weight = 0;
  EXPECT_LT(worst(fit_brush_parameter(votes(0, 288, stretched), 288, free).knots, 288, stretched), 1e-6);
  BrushParameter balanced = fit_brush_parameter(votes(0, 288, stretched), 288, kDefaults).knots;
  double rate = (brush_t(balanced, 288) - brush_t(balanced, 0)) / 288;
  EXPECT_GT(rate, 1.0);
  EXPECT_LT(rate, 1.5);
}

// The largest departure of the fitted t from `want` over the run, every px, leaving out
// 8 px either side of `seam`.
template <class F>
double worst_off_seam(const BrushParameter& knots, double length, double seam, F want) {
  double e = 0;
  for (double s = 0; s <= length; s += 1)
    if (std::abs(s - seam) > 8) e = std::max(e, std::abs(brush_t(knots, s) - want(s)));
  return e;
}

// The votes of two strokes: `first` from s = 0 to a, `second` from b to `end`.
template <class F, class G>
std::vector<BrushVote> two_strokes(F first, double a, G second, double b, double end) {
  std::vector<BrushVote> out = votes(0, a, first, 1);
  for (const BrushVote& v : votes(b, end, second, 2)) out.push_back(v);
  return out;
}

TEST(CoherentSilhouettes, EachGroupParameterizesItsSectionOfTheRun) {
  auto low = [](double s) { return s + 10; };
  auto high = [](double s) { return s + 300; };
  // Two strokes voted for the run: it follows each on its side of their votes' midpoint.
  auto merged = [&](double s) { return s < 100 ? low(s) : high(s); };
  RunBrush both = fit_brush_parameter(two_strokes(low, 96, high, 104, 300), 300, kDefaults);
  EXPECT_LT(worst_off_seam(both.knots, 300, 100, merged), 1e-6);
  EXPECT_EQ(both.path, 102u);  // the run draws the brush path of its largest section (5.)
  RunBrush other = fit_brush_parameter(two_strokes(low, 204, high, 212, 300), 300, kDefaults);
  EXPECT_EQ(other.path, 101u);
  // One stroke whose t jumps (its seam) mid-way: two brush paths.
  auto jumps = [](double s) { return s < 148 ? s : s + 250; };
  EXPECT_LT(worst_off_seam(fit_brush_parameter(votes(0, 200, jumps), 300, kDefaults).knots, 300, 148, jumps), 1e-6);
  // A small group inside a larger one's span claims nothing.
  auto same = [](double s) { return s; };
  auto shifted = [](double s) { return s + 90; };
  std::vector<BrushVote> inside = two_strokes(same, 296, shifted, 120, 136);
  EXPECT_LT(worst(fit_brush_parameter(inside, 300, kDefaults).knots, 300, same), 1e-6);
}

// A claim needs 2 votes: a single one leaves the arc length. Asked to take one, it fixes the
// phase of t over the whole run at rate +1.
TEST(CoherentSilhouettes, OneVoteLeavesTheArcLengthOrFixesThePhase) {
  auto shifted = [](double s) { return s + 5; };
  RunBrush none = fit_brush_parameter(votes(40, 40, shifted), 100, kDefaults);
  EXPECT_TRUE(none.knots.empty());
  EXPECT_EQ(none.path, kNewBrushPath);
  EXPECT_EQ(brush_t({}, 42.0), 42.0);
  CoherenceParams one = kDefaults;
  one.claim_votes = 1;
  EXPECT_LT(worst(fit_brush_parameter(votes(40, 40, shifted), 100, one).knots, 100, shifted), 1e-6);
}

TEST(CoherentSilhouettes, TheTextureRunsAtTheBrushParameter) {
  StrokeStyle style = default_stroke_style();
  StrokeRun run{{{10, 10}, {110, 10}}, false, false, false, {{0, 50}, {100, 150}}};
  BaseStrokeSamples b = base_stroke_samples(run, style);
  ASSERT_GE(b.samples.size(), 2u);
  for (const StrokeSample& q : b.samples) EXPECT_NEAR(q.t, q.s + 50, 1e-9);
  Ribbon r = ribbon(b, style);
  ASSERT_FALSE(r.triangles.empty());
  EXPECT_NEAR(r.triangles[0].uv.x, 50.0 / style.texture_period_px, 1e-6);
}

// The offsets a brush path's walk gives (5.) stay with its t: two runs over which the same
// t runs, shifted by 100 px of s, are both displaced by the walk at t, at full size.
TEST(CoherentSilhouettes, SynthesizedOffsetsFollowTheBrushParameter) {
  OffsetExample drawn{
      80, {{0, 0, 1, false}, {0.25, 3, 1, false}, {0.5, -2, 1, false}, {0.75, 4, 1, false}, {1, 0, 1, false}}};
  StrokeStyle style = default_stroke_style();
  style.offsets = OffsetSynthesizer(drawn).synthesize_period(kBrushOffsetPeriodPx, CounterStream(9));
  StrokeRun a{{{0, 0}, {200, 0}}, false, false, false, {{0, 300}, {200, 500}}};
  StrokeRun b{{{0, 0}, {300, 0}}, false, false, false, {{0, 200}, {300, 500}}};
  double worst = 0, largest = 0;
  size_t samples = 0;
  for (const StrokeRun& run : {a, b})
    for (const StrokeSample& q : base_stroke_samples(run, style).samples) {
      double walk = rubber_stamp(*style.offsets, q.t, 1).displacement_px;  // unscaled: any length
      worst = std::max(worst, std::abs(q.position.y - q.base.y - walk)), largest = std::max(largest, std::abs(walk));
      ++samples;
    }
  EXPECT_GT(samples, 80u);
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(largest, 1.0);  // at full size: scaled by 200 / 1024 it would stay under 0.8 px
}

// The torus's silhouette slide along an orbit, median and p95 (px a frame pair).
std::pair<double, double> torus_slide(bool coherent) {
  using namespace temporal_coherence;
  Scene scene = study_scene(PLUMBAGO_SOURCE_DIR "/scenes/torus_strokes.json",
                            {std::string("strokes.coherent=") + (coherent ? "true" : "false")}, -2.0, 4);
  Carry carry;
  std::vector<double> slide;
  StrokeFrame prev = render_stroke_frame(scene, 0, &carry);
  for (int t = 1; t < 4; ++t) {
    StrokeFrame next = render_stroke_frame(scene, t, &carry);
    EXPECT_EQ(std::isnan(next.coherence_ms), !coherent);
    for (const auto& [kind, m] : pair_measures(prev.strokes, next.strokes))
      if (kind == "silhouette") slide.insert(slide.end(), m.slide_px.begin(), m.slide_px.end());
    prev = std::move(next);
  }
  Stats s = stats(slide);
  return {s.median, s.p95};
}

TEST(CoherentSilhouettes, TheParameterStaysOnTheTorusAlongAnOrbit) {
  auto [base_median, base_p95] = torus_slide(false);
  auto [median, p95] = torus_slide(true);
  std::printf("torus silhouette slide, median / p95 px: arc length %.3f / %.3f, coherent %.3f / %.3f\n", base_median,
              base_p95, median, p95);
  EXPECT_LT(median, 0.5);  // within the sub-pixel drift of a silhouette over the surface
  EXPECT_LT(p95, 2.0);
  EXPECT_GT(base_p95, 5 * p95);  // the seams' drift the coherent parameter removes
}

}  // namespace
}  // namespace plumbago
