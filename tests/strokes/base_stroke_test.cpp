// Base strokes (Kalnins et al. 2002, §4.1, §4.3, §5, App. A; Kalnins et al. 2003): the resampled
// spline against lines and circles, the width and alpha profiles by their known values and
// shapes, offsets and the rubber stamp, pen lifts, and degenerate runs. The ribbons are read
// back through GL's strip order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>

#include "common/strokes/base_stroke.hpp"

namespace plumbago {
namespace {

constexpr double kPeriod = 64;  // texture_period_px of the styles below

// One sample of a ribbon: its vertex at v = 0 (right) and at v = 1 (left).
struct Pair {
  RibbonVertex right, left;
  glm::dvec2 center() const { return (glm::dvec2(right.position) + glm::dvec2(left.position)) / 2.0; }
  double width() const { return glm::distance(glm::dvec2(right.position), glm::dvec2(left.position)); }
  double s() const { return double(right.uv.x) * kPeriod; }
};
using Strip = std::vector<Pair>;

bool same(const RibbonVertex& a, const RibbonVertex& b) {
  return a.position == b.position && a.uv == b.uv && a.alpha == b.alpha;
}

// Splits the triangles into strips, checking GL's strip order on the way: the segment
// from sample j to j + 1 is (R_j, L_j, R_{j+1}), (R_{j+1}, L_j, L_{j+1}); a segment
// continues the strip when it starts where the previous one ended.
std::vector<Strip> strips(const Ribbon& r) {
  EXPECT_EQ(r.triangles.size() % 6, 0u);
  std::vector<Strip> out;
  for (size_t k = 0; k + 6 <= r.triangles.size(); k += 6) {
    const RibbonVertex* t = &r.triangles[k];
    EXPECT_TRUE(same(t[2], t[3]) && same(t[1], t[4])) << "segment " << k / 6 << " is not in strip order";
    EXPECT_EQ(t[0].uv.y, 0.0f);
    EXPECT_EQ(t[1].uv.y, 1.0f);
    bool continues = !out.empty() && same(out.back().back().right, t[0]) && same(out.back().back().left, t[1]);
    if (!continues) out.push_back({{t[0], t[1]}});
    out.back().push_back({t[2], t[5]});
  }
  return out;
}

Strip single_strip(const Ribbon& r) {
  auto all = strips(r);
  EXPECT_EQ(all.size(), 1u);
  return all.empty() ? Strip{} : all[0];
}

// Width 8 px, no taper, fade or halo: the factors under test are switched on one by one.
StrokeStyle plain_style() {
  StrokeStyle s = default_stroke_style();
  s.width_px = 8;
  s.taper_px = 0;
  s.halo_px = 0;
  s.texture_period_px = float(kPeriod);
  return s;
}

// A straight run along +x from (10, 50): its left normal is +y.
StrokeRun horizontal(double length, bool occluded_start = false, bool occluded_end = false) {
  return {{{10, 50}, {10 + length, 50}}, false, occluded_start, occluded_end};
}

std::vector<glm::dvec2> circle(int n, double radius, glm::dvec2 center = {100, 100}) {
  std::vector<glm::dvec2> p;
  for (int i = 0; i < n; ++i) {
    double a = 2 * std::numbers::pi * i / n;
    p.push_back(center + radius * glm::dvec2(std::cos(a), std::sin(a)));
  }
  return p;
}

// --- the spline -------------------------------------------------------------------

// On a line the tangents of Kalnins et al. 2002, §4.1 all have the length of their span's chord: the
// spline is the line at constant speed, whatever the spacing of the input points.
TEST(BaseStroke, ResamplingALineGivesEvenCollinearPoints) {
  glm::dvec2 origin(20, 30), dir(std::cos(0.5), std::sin(0.5));
  std::vector<glm::dvec2> pts;
  for (double t : {0.0, 10.0, 12.0, 40.0, 41.0, 70.0}) pts.push_back(origin + t * dir);
  auto r = catmull_rom_resample(pts, 3.5, false);
  ASSERT_EQ(r.size(), 21u);  // 70 / 3.5 = 20 steps
  for (size_t i = 0; i < r.size(); ++i) {
    glm::dvec2 d = r[i] - origin;
    EXPECT_NEAR(d.x * dir.y - d.y * dir.x, 0.0, 1e-9);  // on the line
    EXPECT_NEAR(glm::dot(d, dir), 3.5 * double(i), 0.01 * 3.5);
  }
  // 100 px: 29 equal steps of 100/29 (sample_px or a little less), both ends included.
  auto r100 = catmull_rom_resample({{0, 0}, {60, 0}, {100, 0}}, 3.5, false);
  ASSERT_EQ(r100.size(), 30u);
  for (size_t i = 0; i + 1 < r100.size(); ++i) EXPECT_NEAR(r100[i + 1].x - r100[i].x, 100.0 / 29, 0.01 * 100.0 / 29);
  EXPECT_EQ(r100.back(), glm::dvec2(100, 0));
}

// Points evenly spaced on a circle: each span is a Hermite cubic with tangents of length
// R sin(theta) (theta the angle between points), inside the circle, deepest at its middle
// at radius R (cos(theta/2) + sin(theta) sin(theta/2) / 4) = R (1 - 3 theta^4 / 128 + ...);
// the dense chords add at most h^2 / (8 R), h <= 0.75 px.
TEST(BaseStroke, ResampledCircleStaysOnTheCircle) {
  const double R = 40;
  for (int n : {24, 48}) {
    double theta = 2 * std::numbers::pi / n;
    double spline = R * (1 - std::cos(theta / 2) - std::sin(theta) * std::sin(theta / 2) / 4);
    double chords = 0.75 * 0.75 / (8 * R);
    auto r = catmull_rom_resample(circle(n, R), 2.0, true);
    double deepest = 0, outside = 0;
    for (glm::dvec2 p : r) {
      deepest = std::max(deepest, R - glm::distance(p, glm::dvec2(100, 100)));
      outside = std::max(outside, glm::distance(p, glm::dvec2(100, 100)) - R);
    }
    std::printf("[base_stroke] circle of %d points: deepest %.6f px (spline %.6f + chords <= %.6f)\n", n, deepest,
                spline, chords);
    EXPECT_LE(outside, 1e-9);
    EXPECT_LE(deepest, spline + chords);
    if (n == 24) {
      EXPECT_GE(deepest, 0.9 * spline);  // samples within 1 px of a span's middle
    }
    // Closed: no repeat of the first point, and the last step (back to it) as long as the others.
    double L = 2 * std::numbers::pi * R;
    ASSERT_EQ(r.size(), size_t(std::ceil(L / 2.0 - 0.01)));
    for (size_t i = 0; i < r.size(); ++i)
      EXPECT_NEAR(glm::distance(r[i], r[(i + 1) % r.size()]), L / double(r.size()), 0.01 * L / double(r.size()));
  }
}

// Parabolic end slopes: (-10, 0), (0, 10), (10, 0) give v_1 = (1, 0) / sqrt(2), so the
// first span has m1 = (10, 0), m0 = 2 (p1 - p0) - m1 = (10, 20): the Hermite cubic
// p0 + m0 t + (p1 - p0 - m0) t^2 is the parabola y = 10 - x^2 / 10, and by symmetry so
// is the second span. Its radius of curvature is at least 5 px: chords within 0.75^2 / 40.
TEST(BaseStroke, OpenEndsAreParabolic) {
  auto r = catmull_rom_resample({{-10, 0}, {0, 10}, {10, 0}}, 0.5, false);
  ASSERT_GT(r.size(), 40u);
  for (glm::dvec2 p : r) EXPECT_NEAR(p.y, 10 - p.x * p.x / 10, 0.75 * 0.75 / 40) << p.x;
}

// The tangents of Kalnins et al. 2002, §4.1 have |v_i| <= 1, so a span's Bézier control points lie within a
// third of its chord of its ends (a parabolic end's within the chord): next to a 1.4 px
// span between two 100 px ones the curve stays within 0.5 px of the corner's box. The
// uniform spline's tangent (p2 - p0) / 2 would swing about 15 px beyond it.
TEST(BaseStroke, UnevenSpacingDoesNotOvershoot) {
  auto r = catmull_rom_resample({{0, 0}, {100, 0}, {101, 1}, {101, 100}}, 0.5, false);
  double right = -1e9, low = 1e9;
  for (glm::dvec2 p : r) right = std::max(right, p.x), low = std::min(low, p.y);
  EXPECT_LE(right, 101.5);
  EXPECT_GE(low, -0.5);
}

// On a curve the steps stay equal within 1% and never exceed sample_px; the ends are kept.
TEST(BaseStroke, ResampledSpacingOnACurve) {
  std::vector<glm::dvec2> wave;
  for (int i = 0; i <= 20; ++i) wave.push_back({7.0 * i, 20 * std::sin(7.0 * i / 15)});
  auto r = catmull_rom_resample(wave, 3.5, false);
  double lo = 1e9, hi = 0;
  for (size_t i = 0; i + 1 < r.size(); ++i) {
    double d = glm::distance(r[i], r[i + 1]);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  EXPECT_LE(hi, 3.5);
  EXPECT_GE(lo, 0.99 * hi);
  EXPECT_EQ(r.front(), wave.front());
  EXPECT_NEAR(glm::distance(r.back(), wave.back()), 0.0, 1e-9);
}

TEST(BaseStroke, ResamplingRepeatedFewAndNonFinitePoints) {
  glm::dvec2 p(3, 4), q(13, 4);
  double nan = std::nan("");
  EXPECT_TRUE(catmull_rom_resample({}, 2, false).empty());
  EXPECT_EQ(catmull_rom_resample({p}, 2, false), std::vector<glm::dvec2>{p});
  EXPECT_EQ(catmull_rom_resample({p, p, p}, 2, true), std::vector<glm::dvec2>{p});
  auto two = catmull_rom_resample({p, q}, 2, false);
  EXPECT_EQ(catmull_rom_resample({p, p, q, q}, 2, false), two);
  EXPECT_EQ(catmull_rom_resample({p, {nan, 1}, q, {1, INFINITY}}, 2, false), two);
  ASSERT_EQ(two.size(), 6u);
  EXPECT_NEAR(two[3].x, 9.0, 1e-12);
  EXPECT_THROW(catmull_rom_resample({p, q}, 0, false), std::invalid_argument);
  EXPECT_THROW(catmull_rom_resample({p, q}, nan, false), std::invalid_argument);
}

// --- width and alpha (Kalnins et al. 2002, §4.1) ----------------------------------------
//
// Checked by values worked out by hand at chosen samples (a run of 140 px sampled every
// 3.5 px, the lengths chosen so that the points lie on samples) and by their shape: 0 at
// the end, rising to the plateau, symmetric; not by their formulas. Width 8 px.

// The sample at arc length s.
const Pair& sample_at(const Strip& strip, double s) {
  for (const Pair& p : strip)
    if (std::abs(p.s() - s) < 1e-4) return p;
  ADD_FAILURE() << "no sample at s = " << s;
  return strip.front();
}

void expect_width_and_alpha(const Strip& strip, double s, double width, double alpha) {
  const Pair& p = sample_at(strip, s);
  EXPECT_NEAR(p.width(), width, 1e-4) << "s = " << s;
  EXPECT_NEAR(p.right.alpha, alpha, 1e-6) << "s = " << s;
  EXPECT_EQ(p.right.alpha, p.left.alpha) << "s = " << s;
}

// The same width and alpha at both ends, neither falling from an end to the middle.
void expect_symmetric_and_rising_inwards(const Strip& strip) {
  const size_t n = strip.size();
  for (size_t j = 0; j < n; ++j) {
    EXPECT_NEAR(strip[j].width(), strip[n - 1 - j].width(), 1e-4) << j;
    EXPECT_NEAR(strip[j].right.alpha, strip[n - 1 - j].right.alpha, 1e-6) << j;
    if (j < n / 2) {
      EXPECT_LE(strip[j].width(), strip[j + 1].width() + 1e-4) << j;
      EXPECT_LE(strip[j].right.alpha, strip[j + 1].right.alpha + 1e-6) << j;
    }
  }
}

// Taper T = 21 px, a quarter ellipse: no width at the end (drawn 2 px wide with alpha 0 by
// the thin-stroke rule), sqrt(3)/2 of it at T/2 (a unit circle's height at 60 degrees),
// all of it from T on; concave in between. Alpha is untouched.
TEST(BaseStroke, TaperHasItsKnownValuesAndShape) {
  StrokeStyle st = plain_style();
  st.taper_px = 21;
  Ribbon r = base_stroke(horizontal(140), st);
  EXPECT_EQ(r.color, glm::vec3(0.1f));
  Strip strip = single_strip(r);
  ASSERT_EQ(strip.size(), 41u);  // 140 / 3.5 = 40 steps
  expect_width_and_alpha(strip, 0, 2, 0);
  expect_width_and_alpha(strip, 10.5, 4 * std::sqrt(3.0), 1);
  for (double s = 21; s <= 119; s += 3.5) expect_width_and_alpha(strip, s, 8, 1);
  expect_symmetric_and_rising_inwards(strip);
  for (size_t j = 2; j < 6; ++j)  // from the first sample wider than 2 px up to T
    EXPECT_LT(strip[j + 1].width() - strip[j].width(), strip[j].width() - strip[j - 1].width()) << j;
  for (const Pair& p : strip) EXPECT_NEAR(p.center().y, 50.0, 1e-5);
}

// Fade F = 21 px: alpha 0 at the end, (3/4)^1.5 = 3 sqrt(3) / 8 at F/2, 1 from F on. The
// width is untouched.
TEST(BaseStroke, FadeHasItsKnownValuesAndShape) {
  StrokeStyle st = plain_style();
  st.fade_px = 21;
  Strip strip = single_strip(base_stroke(horizontal(140), st));
  ASSERT_EQ(strip.size(), 41u);
  expect_width_and_alpha(strip, 0, 8, 0);
  expect_width_and_alpha(strip, 10.5, 8, 3 * std::sqrt(3.0) / 8);
  for (double s = 21; s <= 119; s += 3.5) expect_width_and_alpha(strip, s, 8, 1);
  expect_symmetric_and_rising_inwards(strip);
}

// Halo H = 7 px, only at the ends caused by occlusion and at none of a closed run: at an
// occluded end no width (drawn 2 px wide) and alpha 0; at H/2, h = 1/2, 1 - h^2 = 3/4, the
// width x (3/4)^(1/4) and alpha (3/4)^5 = 243/1024; from H on untouched.
TEST(BaseStroke, HaloOnlyAtOccludedEnds) {
  StrokeStyle st = plain_style();
  st.halo_px = 7;
  auto strip_of = [&](bool start, bool end) {
    Strip strip = single_strip(base_stroke(horizontal(140, start, end), st));
    EXPECT_EQ(strip.size(), 41u);
    return strip;
  };
  auto expect_halo_at = [](const Strip& strip, double s_end, double s_half) {
    expect_width_and_alpha(strip, s_end, 2, 0);
    expect_width_and_alpha(strip, s_half, 8 * std::sqrt(std::sqrt(0.75)), 243.0 / 1024);
  };
  for (const Pair& p : strip_of(false, false)) {
    EXPECT_NEAR(p.width(), 8.0, 1e-4);
    EXPECT_EQ(p.right.alpha, 1.0f);
  }
  Strip start = strip_of(true, false), end = strip_of(false, true), both = strip_of(true, true);
  expect_halo_at(start, 0, 3.5);
  for (double s = 7; s <= 140; s += 3.5) expect_width_and_alpha(start, s, 8, 1);
  expect_halo_at(end, 140, 136.5);
  for (double s = 0; s <= 133; s += 3.5) expect_width_and_alpha(end, s, 8, 1);
  for (size_t j = 0; j < start.size() && j < end.size(); ++j) {
    EXPECT_NEAR(start[j].width(), end[end.size() - 1 - j].width(), 1e-4) << j;
    EXPECT_EQ(start[j].right.alpha, end[end.size() - 1 - j].right.alpha) << j;
  }
  expect_halo_at(both, 0, 3.5);
  expect_halo_at(both, 140, 136.5);
  expect_symmetric_and_rising_inwards(both);
  for (const Pair& p : single_strip(base_stroke({circle(48, 40), true, true, true}, st))) {
    EXPECT_NEAR(p.width(), 8.0, 1e-4);
    EXPECT_EQ(p.right.alpha, 1.0f);
  }
}

// Reading (stroke_style.hpp): flare 1 doubles the width at the ends, leaves it at the
// middle and is linear in between (16, 12 and 8 px at 0, L/4 and L/2); alpha untouched.
TEST(BaseStroke, FlareWidensTheEnds) {
  StrokeStyle st = plain_style();
  st.flare = 1;
  Strip strip = single_strip(base_stroke(horizontal(140), st));
  ASSERT_EQ(strip.size(), 41u);
  expect_width_and_alpha(strip, 0, 16, 1);
  expect_width_and_alpha(strip, 35, 12, 1);
  expect_width_and_alpha(strip, 70, 8, 1);
  expect_width_and_alpha(strip, 140, 16, 1);
  for (size_t j = 0; j + 1 < strip.size(); ++j)
    EXPECT_NEAR(std::abs(strip[j + 1].width() - strip[j].width()), 8.0 / 20, 1e-4) << j;
}

// Below 2 px a stroke is drawn 2 px wide, its alpha x (width / 2)^2; from 2 px on as it is.
TEST(BaseStroke, ThinStrokesAreDrawnTwoPixelsWideAndFainter) {
  StrokeStyle st = plain_style();
  st.alpha = 0.8f;
  const std::tuple<double, double, double> cases[] = {
      // width, drawn width, alpha
      {1.0, 2.0, 0.2}, {1.5, 2.0, 0.45}, {0.5, 2.0, 0.05}, {2.0, 2.0, 0.8}, {2.25, 2.25, 0.8}, {3.0, 3.0, 0.8}};
  for (auto [width, drawn, alpha] : cases) {
    st.width_px = float(width);
    for (const Pair& p : single_strip(base_stroke(horizontal(70), st))) {
      EXPECT_NEAR(p.width(), drawn, 1e-4) << width;
      EXPECT_NEAR(p.right.alpha, alpha, 1e-6) << width;
    }
  }
}

// --- offsets (Kalnins et al. 2002, §4.3, §5, App. A; Kalnins et al. 2003)
// -------------------------------------------------------

// A constant displacement d moves every sample by d along the left normal, times
// min(L / L_drawn, 1).
TEST(BaseStroke, ConstantOffsetShiftsAlongTheNormal) {
  glm::dvec2 start(30, 20), dir(0.6, 0.8), normal(-0.8, 0.6);
  StrokeStyle st = plain_style();
  st.offsets = OffsetExample{50, {{0.3, 3.0, 1.0, false}}};
  for (double length : {140.0, 25.0}) {
    double d = 3.0 * std::min(length / 50, 1.0);
    Strip strip = single_strip(base_stroke({{start, start + length * dir}, false, false, false}, st));
    ASSERT_GT(strip.size(), 5u);
    for (const Pair& p : strip) {
      glm::dvec2 expected = start + p.s() * dir + d * normal;
      EXPECT_NEAR(glm::distance(p.center(), expected), 0.0, 1e-4) << "length " << length << ", s " << p.s();
      EXPECT_NEAR(p.width(), 8.0, 1e-4);
    }
  }
}

TEST(BaseStroke, RubberStampInterpolatesAndRepeatsWithTheExamplesLength) {
  OffsetExample tent{40, {{0, 0, 1, false}, {0.5, 4, 0.5, false}, {1, 0, 1, false}}};
  for (double k : {0.0, 1.0, 7.0}) {
    StampedOffset at20 = rubber_stamp(tent, 20 + 40 * k, 500), at10 = rubber_stamp(tent, 10 + 40 * k, 500);
    EXPECT_NEAR(at20.displacement_px, 4.0, 1e-12);
    EXPECT_NEAR(at20.pressure, 0.5, 1e-12);
    EXPECT_NEAR(at10.displacement_px, 2.0, 1e-12);
    EXPECT_NEAR(at10.pressure, 0.75, 1e-12);
    EXPECT_TRUE(at10.pen_down);
  }
  EXPECT_NEAR(rubber_stamp(tent, 20, 10).displacement_px, 1.0, 1e-12);  // run of 10 px: x 10/40
  EXPECT_NEAR(rubber_stamp(tent, 20, 10).pressure, 0.5, 1e-12);         // pressure is not scaled
  // Before the first offset the last segment wraps into the next period: t = 0.1 lies
  // between -2 at t = 0.75 and 2 at t = 1.25, 0.7 of the way.
  OffsetExample wrap{40, {{0.25, 2, 1, false}, {0.75, -2, 1, false}}};
  EXPECT_NEAR(rubber_stamp(wrap, 4, 100).displacement_px, 0.8, 1e-12);
  EXPECT_NEAR(rubber_stamp(wrap, 0, 100).displacement_px, 0.0, 1e-12);

  // On a ribbon: samples every 2.5 px, so one period is 16 samples.
  StrokeStyle st = plain_style();
  st.sample_px = 2.5f;
  st.offsets = tent;
  Strip strip = single_strip(base_stroke(horizontal(140), st));
  ASSERT_EQ(strip.size(), 57u);
  EXPECT_NEAR(strip[8].center().y, 54.0, 1e-4);  // s = 20
  for (size_t j = 0; j + 16 < strip.size(); ++j) EXPECT_NEAR(strip[j].center().y, strip[j + 16].center().y, 1e-4) << j;
}

// An example made to span its run (a decal's pressure, a synthesized example) does not
// repeat: its spline may be a little longer than the run it was made for, and the end holds
// the last offset (its lift too) where a repeating example would start over.
TEST(BaseStroke, AnExampleMadeForItsRunHoldsItsEnds) {
  OffsetExample made{40, {{0.25, 2, 0.5, false}, {0.75, -2, 1, false}, {1, 3, 0.8, false}}, false};
  EXPECT_NEAR(rubber_stamp(made, 40.5, 40.5).displacement_px, 3.0, 1e-12);  // past its end: the last offset
  EXPECT_NEAR(rubber_stamp(made, 40.5, 40.5).pressure, 0.8, 1e-12);
  EXPECT_NEAR(rubber_stamp(made, 4, 40.5).displacement_px, 2.0, 1e-12);  // before its first: the first
  made.repeats = true;
  // Repeating, it wraps: t = 1.0125, from 3 at t = 1 towards 2 at t = 1.25, 0.05 of the way.
  EXPECT_NEAR(rubber_stamp(made, 40.5, 40.5).displacement_px, 2.95, 1e-12);
  // A lift from its last offset lasts to the run's end: one piece, ending where it starts.
  StrokeStyle st = plain_style();
  st.offsets = OffsetExample{100, {{0, 0, 1, false}, {0.5, 0, 1, true}}, false};
  auto pieces = strips(base_stroke(horizontal(140), st));
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(pieces[0].back().s(), 50, 1e-4);
}

// A break lifts the pen from its offset to the next: over t in (0.5, 0.75) of every
// 40 px period nothing is drawn, and samples sit exactly where the pen lifts and lands.
TEST(BaseStroke, BreaksSplitTheRibbon) {
  StrokeStyle st = plain_style();
  st.offsets = OffsetExample{40, {{0, 0, 1, false}, {0.5, 0, 1, true}, {0.75, 0, 1, false}}};
  auto pieces = strips(base_stroke(horizontal(140), st));
  std::vector<std::pair<double, double>> expected = {{0, 20}, {30, 60}, {70, 100}, {110, 140}};
  ASSERT_EQ(pieces.size(), expected.size());
  for (size_t i = 0; i < pieces.size(); ++i) {
    EXPECT_NEAR(pieces[i].front().s(), expected[i].first, 1e-4);
    EXPECT_NEAR(pieces[i].back().s(), expected[i].second, 1e-4);
    EXPECT_NEAR(pieces[i].front().center().x, 10 + expected[i].first, 1e-4);
    for (size_t j = 0; j + 1 < pieces[i].size(); ++j) EXPECT_LE(pieces[i][j + 1].s() - pieces[i][j].s(), 3.5 + 1e-4);
  }
  // A break on the last offset at t = 1 with the first at t = 0 lifts the pen for no length.
  st.offsets = OffsetExample{40, {{0, 0, 1, false}, {1, 0, 1, true}}};
  EXPECT_EQ(strips(base_stroke(horizontal(140), st)).size(), 1u);
}

// A pen change 1e-4 px from an even sample takes its place (a segment that short has no
// reliable direction in float), and one 0.01 px from the run's start gives way to the start.
TEST(BaseStroke, PenChangesNearOtherSamplesLeaveNoSegmentUnder005Px) {
  StrokeStyle st = plain_style();
  st.sample_px = 4;  // even samples at 0, 4, ..., 140
  double near_even = 0.5 + 1e-4 / 40;
  st.offsets = OffsetExample{40, {{0, 0, 1, false}, {near_even, 0, 1, true}, {0.75, 0, 1, false}}};
  std::vector<StrokeSample> q = base_stroke_samples(horizontal(140), st).samples;
  for (size_t j = 0; j + 1 < q.size(); ++j) EXPECT_GE(q[j + 1].s - q[j].s, 0.05) << "s " << q[j].s;
  for (double lift : {20.0001, 60.0001, 100.0001}) {
    auto at = std::find_if(q.begin(), q.end(), [&](const StrokeSample& x) { return std::abs(x.s - lift) < 1e-9; });
    ASSERT_NE(at, q.end()) << "no sample where the pen lifts at " << lift;
    EXPECT_FALSE(at->pen_down_after);
    EXPECT_TRUE((at - 1)->pen_down_after);
    EXPECT_NEAR((at - 1)->s, lift - 4.0001, 1e-9);  // the even sample at 20 gave way
  }
  st.offsets = OffsetExample{40, {{0.01 / 40, 0, 1, true}, {0.5, 0, 1, false}}};  // lifts at 0.01, 40.01, ...
  q = base_stroke_samples(horizontal(140), st).samples;
  EXPECT_EQ(q[1].s, 4.0);  // no sample at 0.01: the lift starts at the start
  EXPECT_FALSE(q[0].pen_down_after);
  EXPECT_TRUE(std::any_of(q.begin(), q.end(), [](const StrokeSample& x) { return std::abs(x.s - 40.01) < 1e-9; }));
}

// The drawn pieces of a run's samples: [s, s] from a sample whose pen goes down to the
// sample where it lifts again.
std::vector<std::pair<double, double>> drawn_pieces(const std::vector<StrokeSample>& q) {
  std::vector<std::pair<double, double>> out;
  for (size_t j = 0; j + 1 < q.size(); ++j) {
    if (!q[j].pen_down_after) continue;
    if (j == 0 || !q[j - 1].pen_down_after) out.push_back({q[j].s, q[j].s});
    out.back().second = q[j + 1].s;
  }
  return out;
}

// With a brush parameter t (Kalnins et al. 2003), a repeating example is stamped at t, and
// its lifts lie where t takes them: shifted, reversed, or on either side of a jump of t.
TEST(BaseStroke, RepeatingOffsetsFollowTheBrushParameter) {
  StrokeStyle st = plain_style();
  st.offsets = OffsetExample{40, {{0, 0, 1, false}, {0.5, 3, 1, true}, {0.75, -2, 1, false}}};  // lifts t in (20, 30)
  struct Case {
    BrushParameter brush;
    std::vector<std::pair<double, double>> pieces;
  };
  for (const Case& c : {Case{{{0, 15}, {140, 155}}, {{0, 5}, {15, 45}, {55, 85}, {95, 125}, {135, 140}}},
                        Case{{{0, 200}, {140, 60}}, {{0, 10}, {20, 50}, {60, 90}, {100, 130}}},
                        Case{{{0, 0}, {70, 70}, {70, 300}, {140, 370}}, {{0, 20}, {30, 60}, {80, 110}, {120, 140}}}}) {
    StrokeRun run = horizontal(140);
    run.brush = c.brush;
    std::vector<StrokeSample> q = base_stroke_samples(run, st).samples;
    auto pieces = drawn_pieces(q);
    ASSERT_EQ(pieces.size(), c.pieces.size()) << "brush from t = " << c.brush[0].y;
    for (size_t i = 0; i < pieces.size(); ++i) {
      EXPECT_NEAR(pieces[i].first, c.pieces[i].first, 1e-6);
      EXPECT_NEAR(pieces[i].second, c.pieces[i].second, 1e-6);
    }
    for (const StrokeSample& x : q) {
      EXPECT_NEAR(x.t, brush_t(c.brush, x.s), 1e-9);
      EXPECT_NEAR(x.position.y - x.base.y, rubber_stamp(*st.offsets, x.t, 140).displacement_px, 1e-9) << "s " << x.s;
    }
  }
}

// An example made to span its run (a synthesized one) stays on arc length under a brush.
TEST(BaseStroke, OffsetsMadeForTheirRunStayOnArcLength) {
  StrokeStyle st = plain_style();
  st.offsets = OffsetExample{140, {{0, 0, 1, false}, {0.5, 3, 1, true}, {0.75, -2, 1, false}}, false};
  StrokeRun run = horizontal(140);
  std::vector<StrokeSample> plain = base_stroke_samples(run, st).samples;
  run.brush = {{0, 15}, {140, 155}};
  std::vector<StrokeSample> brushed = base_stroke_samples(run, st).samples;
  ASSERT_EQ(plain.size(), brushed.size());
  for (size_t j = 0; j < plain.size(); ++j) {
    EXPECT_EQ(plain[j].position, brushed[j].position);
    EXPECT_EQ(plain[j].pen_down_after, brushed[j].pen_down_after);
    EXPECT_NEAR(brushed[j].t, plain[j].s + 15, 1e-9);
  }
}

TEST(BaseStroke, PressureScalesWidthAndOptionallyAlpha) {
  StrokeStyle st = plain_style();
  st.offsets = OffsetExample{40, {{0, 0, 0.5, false}}};
  for (bool alpha : {false, true}) {
    st.pressure_alpha = alpha;
    for (const Pair& p : single_strip(base_stroke(horizontal(70), st))) {
      EXPECT_NEAR(p.width(), 4.0, 1e-4);
      EXPECT_NEAR(p.right.alpha, alpha ? 0.5 : 1.0, 1e-6);
    }
  }
}

// --- closed runs and degenerate input ----------------------------------------------

// A closed run has no ends: full width all round, u runs on to L at the closing sample,
// which is the first again, with the same normal.
TEST(BaseStroke, ClosedRunWrapsAround) {
  StrokeStyle st = plain_style();
  st.taper_px = 24;
  st.fade_px = 10;
  Strip strip = single_strip(base_stroke({circle(48, 40), true, false, false}, st));
  for (const Pair& p : strip) {
    EXPECT_NEAR(p.width(), 8.0, 1e-4);
    EXPECT_EQ(p.right.alpha, 1.0f);
  }
  EXPECT_EQ(strip.front().s(), 0.0);
  EXPECT_NEAR(strip.back().s(), 2 * std::numbers::pi * 40, 0.001 * 2 * std::numbers::pi * 40);
  EXPECT_NEAR(glm::distance(glm::dvec2(strip.front().right.position), glm::dvec2(strip.back().right.position)), 0,
              1e-4);
  EXPECT_NEAR(glm::distance(glm::dvec2(strip.front().left.position), glm::dvec2(strip.back().left.position)), 0, 1e-4);
}

bool all_finite(const Ribbon& r) {
  for (const RibbonVertex& v : r.triangles)
    for (float x : {v.position.x, v.position.y, v.uv.x, v.uv.y, v.alpha})
      if (!std::isfinite(x)) return false;
  return true;
}

TEST(BaseStroke, DegenerateRunsGiveEmptyOrFiniteRibbons) {
  StrokeStyle st = default_stroke_style();
  glm::dvec2 p(5, 5);
  EXPECT_TRUE(base_stroke({{}, false, false, false}, st).triangles.empty());
  EXPECT_TRUE(base_stroke({{p}, false, true, true}, st).triangles.empty());
  EXPECT_TRUE(base_stroke({{p, p, p, p}, true, false, false}, st).triangles.empty());
  EXPECT_TRUE(base_stroke({{p, p + glm::dvec2(1e-7, 0)}, false, false, false}, st).triangles.empty());

  std::vector<StrokeRun> odd = {
      {{p, {std::nan(""), 3}, {40, 5}, {INFINITY, 0}}, false, true, false},  // non-finite points dropped
      {{{0, 0}, {50, 0}, {0, 0}}, false, false, false},                      // hairpin
      {{{0, 0}, {50, 0}, {50, 0}, {0, 0}}, false, false, true},              // hairpin, repeated point
      {{{0, 0}, {30, 10}}, true, false, false},                              // closed with 2 points: drawn open
      {circle(12, 2), true, false, false},                                   // tighter than the width
  };
  st.offsets = OffsetExample{8, {{0, 6, 1, false}, {0.5, -6, 0.2, false}}};  // larger than the curvature radius
  for (const StrokeRun& run : odd) {
    Ribbon r = base_stroke(run, st);
    EXPECT_FALSE(r.triangles.empty());
    EXPECT_TRUE(all_finite(r));
    strips(r);  // in strip order
  }
  st.sample_px = 0;
  EXPECT_THROW(base_stroke({{p, {20, 5}}, false, false, false}, st), StrokeStyleError);
}

}  // namespace
}  // namespace plumbago
