// Synthesis of stroke offsets by example (Kalnins et al. 2002 Appendix A):
// resampling, seeding, the statistics the chain keeps (mean, variance, autocorrelation,
// period) over long strokes, the Q-learning's avoidance of a dead end, the offset list for
// rubber_stamp, degenerate examples, and controls showing that the statistical checks
// fail for a chain without its window or with uniform transitions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "common/strokes/base_stroke.hpp"
#include "common/strokes/offset_synthesis.hpp"

namespace plumbago {
namespace {

constexpr double kLongStroke = 20000;  // px: 5001 offsets at 4 px
constexpr int kLags = 8;

// An example of length L whose offsets sample f (px along -> px) every dt px.
OffsetExample sampled(double length, double dt, const std::function<double(double)>& f) {
  OffsetExample e;
  e.length_px = length;
  int n = int(std::round(length / dt));
  for (int k = 0; k <= n; ++k) {
    double s = k * length / n;
    e.offsets.push_back({s / length, f(s), 1.0, false});
  }
  return e;
}

OffsetExample sine(double period, double periods = 8, double amplitude = 3) {
  return sampled(periods * period, 1,
                 [=](double s) { return amplitude * std::sin(2 * std::numbers::pi * s / period); });
}

OffsetExample sawtooth() {  // period 60 px, a ramp from -2 to 2 px, then a drop
  return sampled(480, 1, [](double s) { return -2 + 4 * (s / 60 - std::floor(s / 60)); });
}

// Random-walk-like: AR(1), x <- 0.9 x + 2 u, u a sum of 4 uniforms in [-1/2, 1/2), one
// offset every 4 px over 800 px.
OffsetExample random_walk() {
  Rng rng(5, "offset-synthesis-test-walk");
  OffsetExample e;
  e.length_px = 800;
  double x = 0;
  for (int k = 0; k <= 200; ++k) {
    double u = 0;
    for (int i = 0; i < 4; ++i) u += rng.uniform() - 0.5;
    x = 0.9 * x + 2 * u;
    e.offsets.push_back({k / 200.0, x, 1.0, false});
  }
  return e;
}

// Mean, variance (1/n) and autocorrelation r_k = sum (x_t - mean)(x_{t+k} - mean) /
// ((n - k) variance), lags 1..lags (r[k-1] is lag k).
struct Stats {
  double mean = 0, variance = 0;
  std::vector<double> r;
};

Stats stats(const std::vector<double>& x, int lags) {
  Stats s;
  double n = double(x.size());
  for (double v : x) s.mean += v;
  s.mean /= n;
  for (double v : x) s.variance += (v - s.mean) * (v - s.mean);
  s.variance /= n;
  for (int k = 1; k <= lags; ++k) {
    double c = 0;
    for (size_t t = 0; t + k < x.size(); ++t) c += (x[t] - s.mean) * (x[t + k] - s.mean);
    s.r.push_back(c / (double(x.size()) - k) / s.variance);
  }
  return s;
}

// The dominant period in offsets: past the first lag where r <= 0, the lag of the largest
// r, refined by the parabola through it and its neighbours; 0 when it is the last lag.
double dominant_period(const std::vector<double>& r) {
  size_t k = 0;
  while (k < r.size() && r[k] > 0) ++k;
  if (k == r.size()) return 0;
  size_t best = k;
  for (; k < r.size(); ++k)
    if (r[k] > r[best]) best = k;
  if (best == 0 || best + 1 >= r.size()) return 0;
  double a = r[best - 1], b = r[best], c = r[best + 1];
  return double(best + 1) + 0.5 * (a - c) / (a - 2 * b + c);
}

// How far a synthesis strays from its example's statistics: the mean in units of the
// example's standard deviation, the variance as a ratio - 1, the autocorrelation at lags
// 1..8 (largest absolute difference).
struct Deviation {
  double mean = 0, variance = 0, autocorrelation = 0;
};

Deviation deviation(const OffsetSynthesizer& synth, const OffsetExample& e, uint32_t seed) {
  Stats want = stats(resample_offsets(e), kLags);
  Stats got = stats(synth.synthesize(kLongStroke, seed, "deviation"), kLags);
  Deviation d;
  d.mean = std::abs(got.mean - want.mean) / std::sqrt(want.variance);
  d.variance = std::abs(got.variance / want.variance - 1);
  for (int k = 0; k < kLags; ++k) d.autocorrelation = std::max(d.autocorrelation, std::abs(got.r[k] - want.r[k]));
  return d;
}

// The bounds. The sine and the sawtooth are exactly periodic, so the chain copies their
// shape; what strays comes from the 5001-offset window of the estimate and from the jumps
// between equivalent phases: over 400 seeds the worst was 0.021 sd (mean), 0.019
// (variance) and 0.055 (autocorrelation), bounds about 2.5x that. The random walk strays
// more, and not like an AR(1) series (whose standard errors over 5001 offsets would be
// about 0.05): much of its variance is in one excursion (13 samples, 1.6 to 3.4 sd above
// the mean), entered along one path only, so it depends on how many times in 5001 steps
// the chain passes through it (about 20, Poisson-like). Over 400 seeds: mean -0.067 +-
// 0.055 sd, variance ratio - 1 -0.032 +- 0.082, worst autocorrelation difference 0.108;
// the bounds are the bias + about 4 standard deviations.
struct Bound {
  double mean, variance, autocorrelation;
};
constexpr Bound kPeriodicBound{0.05, 0.05, 0.08};
constexpr Bound kWalkBound{0.3, 0.35, 0.15};

bool within(const Deviation& d, const Bound& b) {
  return d.mean <= b.mean && d.variance <= b.variance && d.autocorrelation <= b.autocorrelation;
}

TEST(OffsetSynthesis, ResamplesEveryFourPixels) {
  OffsetExample e;  // displacement 10 t, a break in the middle, one offset not finite
  e.length_px = 100;
  e.offsets = {{0.0, 0.0, 1.0, false},
               {0.5, 5.0, 0.5, true},
               {0.7, std::numeric_limits<double>::quiet_NaN(), 1.0, false},
               {1.0, 10.0, 1.0, false}};
  std::vector<double> r = resample_offsets(e);
  ASSERT_EQ(r.size(), 26u);  // 0, 4, ..., 100 px
  for (size_t k = 0; k < r.size(); ++k) EXPECT_NEAR(r[k], 10 * (4.0 * k / 100), 1e-12) << k;
  EXPECT_EQ(resample_offsets(e, 10).size(), 11u);
  e.length_px = 99;  // 0 .. 96 px
  EXPECT_EQ(resample_offsets(e).size(), 25u);
  // Held before the first offset and after the last.
  OffsetExample inner{40, {{0.25, 1.0, 1.0, false}, {0.75, 3.0, 1.0, false}}};
  std::vector<double> held = resample_offsets(inner);
  ASSERT_EQ(held.size(), 11u);
  EXPECT_EQ(held.front(), 1.0);
  EXPECT_EQ(held.back(), 3.0);
  EXPECT_NEAR(held[5], 2.0, 1e-12);
  EXPECT_THROW(resample_offsets(e, 0), std::invalid_argument);
  EXPECT_THROW(resample_offsets(e, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

TEST(OffsetSynthesis, SeededFromSeedAndName) {
  OffsetSynthesizer synth(random_walk());
  std::vector<double> a = synth.synthesize(2000, 7, "crease-12");
  ASSERT_EQ(a.size(), 501u);
  EXPECT_EQ(a, synth.synthesize(2000, 7, "crease-12"));
  EXPECT_EQ(a, synthesize_offsets(random_walk(), 2000, 7, "crease-12"));  // the one-call form
  std::vector<double> other_seed = synth.synthesize(2000, 8, "crease-12");
  std::vector<double> other_name = synth.synthesize(2000, 7, "crease-13");
  EXPECT_NE(a, other_seed);
  EXPECT_NE(a, other_name);
  // A longer stroke begins the same way (one random number per offset).
  std::vector<double> longer = synth.synthesize(4000, 7, "crease-12");
  EXPECT_TRUE(std::equal(a.begin(), a.end(), longer.begin()));
}

TEST(OffsetSynthesis, ChainFollowsAppendixA) {
  OffsetExample e = random_walk();
  OffsetSynthesizer synth(e);
  ASSERT_TRUE(synth.is_markov());
  ASSERT_EQ(synth.state_count(), 201u);
  EXPECT_GT(synth.iterations(), 0);
  EXPECT_LE(synth.iterations(), 100);
  if (synth.iterations() < 100) {
    EXPECT_LT(synth.last_change(), 10.0);
  }
  EXPECT_GT(synth.rho(), 0.0);
  const size_t n = synth.state_count();
  for (size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (size_t j = 0; j < n; ++j) sum += synth.probability(i, j);
    EXPECT_NEAR(sum, 1.0, 1e-9) << "row " << i;
    // Sample r < 3 (whose window holds the example's start) only from a sample before it.
    for (size_t r = 0; r < 3; ++r)
      if (i >= r) {
        EXPECT_EQ(synth.probability(i, r), 0.0) << i << " -> " << r;
      }
  }
  EXPECT_GT(synth.probability(0, 1), 0.0);
  // Without Q-learning D'' = C, and the natural successor (cost 0) is the likeliest step.
  OffsetSynthesisOptions no_q;
  no_q.max_iterations = 0;
  OffsetSynthesizer greedy(e, no_q);
  EXPECT_EQ(greedy.iterations(), 0);
  for (size_t i = 0; i + 1 < n; ++i)
    for (size_t j = 0; j < n; ++j)
      EXPECT_LE(greedy.probability(i, j), greedy.probability(i, i + 1) * (1 + 1e-9)) << i << " -> " << j;
}

TEST(OffsetSynthesis, KeepsTheExamplesStatistics) {
  struct Case {
    const char* name;
    OffsetExample example;
    Bound bound;
  };
  for (const Case& c :
       {Case{"sine 50 px", sine(50), kPeriodicBound}, Case{"sawtooth 60 px", sawtooth(), kPeriodicBound},
        Case{"random walk", random_walk(), kWalkBound}}) {
    OffsetSynthesizer synth(c.example);
    ASSERT_TRUE(synth.is_markov()) << c.name;
    for (uint32_t seed : {1u, 2u, 3u}) {
      Deviation d = deviation(synth, c.example, seed);
      std::printf(
          "  %-15s seed %u: |mean| %.4f sd (<= %.2f), |var ratio - 1| %.4f (<= %.2f), max |r_k diff| %.4f (<= %.2f)\n",
          c.name, seed, d.mean, c.bound.mean, d.variance, c.bound.variance, d.autocorrelation, c.bound.autocorrelation);
      EXPECT_LE(d.mean, c.bound.mean) << c.name << " seed " << seed;
      EXPECT_LE(d.variance, c.bound.variance) << c.name << " seed " << seed;
      EXPECT_LE(d.autocorrelation, c.bound.autocorrelation) << c.name << " seed " << seed;
    }
  }
}

// Dominant period within 1 px (a quarter of the 4 px step) of the example's.
TEST(OffsetSynthesis, PeriodicExampleKeepsItsPeriod) {
  for (double period : {37.0, 50.0, 64.0}) {
    OffsetSynthesizer synth(sine(period));
    for (uint32_t seed : {1u, 2u}) {
      Stats s = stats(synth.synthesize(kLongStroke, seed, "period"), 40);
      double measured = 4 * dominant_period(s.r);
      std::printf("  sine of period %.0f px, seed %u: dominant period %.3f px\n", period, seed, measured);
      EXPECT_NEAR(measured, period, 1.0) << "seed " << seed;
    }
  }
}

// A dead end: example B copies two periods of example A (a sine), then climbs 3 px per
// sample to 24 px and ends there. Whatever follows B's end is a jump: back into the climb
// (about (3 + 3 + 3) / 4 = 2.25 px of window difference, cost 5 px^2, and again at the
// next step) or down to A (about 15 px, cost over 200 px^2). Stepping from B's copy into
// the climb costs 0 now (B's natural successor) but a lot later, while stepping to A's
// equivalent sample costs about 0.2 px^2 now and nothing later. Without Q-learning the
// chain climbs, and at the top it keeps jumping back into the climb (5 < 200); Q-learning
// sees the future cost, and the chain leaves B before the climb.
TEST(OffsetSynthesis, QLearningAvoidsTheDeadEnd) {
  auto wave = [](double s) { return 3 * std::sin(2 * std::numbers::pi * s / 64); };
  std::vector<OffsetExample> examples{sampled(512, 1, wave),
                                      sampled(160, 1, [&](double s) { return s <= 128 ? wave(s) : 0.75 * (s - 128); })};
  // States: A 0..128, B 129..169; B's climb begins at its sample 33 (132 px): state 162.
  const size_t climb = 129 + 33;
  auto into_climb = [&](const OffsetSynthesizer& synth) {
    EXPECT_NEAR(synth.values()[climb], 3.0, 1e-12);
    EXPECT_NEAR(synth.values()[climb - 1], 0.0, 1e-12);
    EXPECT_NEAR(synth.values().back(), 24.0, 1e-12);
    return synth.probability(climb - 1, climb);
  };
  OffsetSynthesizer learned(examples);
  OffsetSynthesisOptions no_q;
  no_q.max_iterations = 0;
  OffsetSynthesizer greedy(examples, no_q);
  double p_learned = into_climb(learned), p_greedy = into_climb(greedy);
  std::printf("  P(step into the climb): %.3g with Q-learning (%d iterations, last change %.3g), %.3g without\n",
              p_learned, learned.iterations(), learned.last_change(), p_greedy);
  EXPECT_LT(p_learned, 1e-3);
  EXPECT_GT(p_greedy, 0.2);
  // Over a long stroke: how often the chain is on the climb (above 5 px, where A never is).
  auto climbing = [&](const OffsetSynthesizer& synth) {
    long count = 0;
    for (uint32_t seed : {1u, 2u, 3u}) {
      std::vector<double> y = synth.synthesize(kLongStroke, seed, "dead-end");
      count += std::count_if(y.begin(), y.end(), [](double v) { return v > 5; });
    }
    return count;
  };
  long c_learned = climbing(learned), c_greedy = climbing(greedy);
  std::printf("  offsets above 5 px in 3 x 5001: %ld with Q-learning, %ld without\n", c_learned, c_greedy);
  EXPECT_EQ(c_learned, 0);
  EXPECT_GT(c_greedy, 1000);
}

TEST(OffsetSynthesis, OffsetListForRubberStamp) {
  OffsetSynthesizer synth(sine(50));
  for (double length : {1000.0, 998.0, 2.5}) {
    OffsetExample list = synth.synthesize_example(length, 3, "stamp");
    std::vector<double> y = synth.synthesize(std::max(length, 1.0), 3, "stamp");
    EXPECT_EQ(list.length_px, std::max(length, 1.0));
    ASSERT_GE(list.offsets.size(), 2u);
    EXPECT_EQ(list.offsets.front().t, 0.0);
    EXPECT_EQ(list.offsets.back().t, 1.0);
    for (size_t k = 1; k < list.offsets.size(); ++k) EXPECT_GT(list.offsets[k].t, list.offsets[k - 1].t);
    StrokeStyle style = default_stroke_style();
    style.offsets = list;
    EXPECT_NO_THROW(validate_stroke_style(style, "synthesized"));
    // rubber_stamp over a run of that length gives the synthesized offset every 4 px.
    for (size_t k = 0; 4.0 * k < list.length_px; ++k)
      EXPECT_NEAR(rubber_stamp(list, 4.0 * k, list.length_px).displacement_px, y[k], 1e-9) << length << " px, " << k;
    // ... and the last offset lies on the segment from the last two synthesized.
    size_t k0 = size_t(list.length_px / 4);
    double f = list.length_px / 4 - double(k0);
    double last = k0 + 1 < y.size() ? y[k0] + f * (y[k0 + 1] - y[k0]) : y[k0];
    EXPECT_NEAR(list.offsets.back().displacement_px, last, 1e-9);
  }
  EXPECT_EQ(synthesize_offset_example(sine(50), 1000, 3, "stamp").offsets.size(), 251u);
}

// A brush path's offsets (common/strokes/coherent_silhouettes.hpp 5.): the walk as a periodic
// example, drawn at full size, which on [0, L] is the run's own synthesis for L up to its
// period less a step (then its last offset runs into its first): a new run draws what the
// 2002 synthesis draws along its arc length.
TEST(OffsetSynthesis, PeriodOfABrushPathStartsAsTheRunsOwn) {
  OffsetSynthesizer synth(random_walk());
  const double period = 1024;
  OffsetExample periodic = synth.synthesize_period(period, CounterStream(77));
  EXPECT_TRUE(periodic.repeats);
  EXPECT_FALSE(periodic.scales);
  EXPECT_EQ(periodic.offsets.size(), 256u);
  StrokeStyle style = default_stroke_style();
  style.offsets = periodic;
  EXPECT_NO_THROW(validate_stroke_style(style, "brush path"));
  for (double length : {1020.0, 300.0, 37.5}) {
    OffsetExample own = synth.synthesize_example(length, CounterStream(77));
    double worst = 0;
    for (double s = 0; s <= length; s += 0.25)
      worst = std::max(worst, std::abs(rubber_stamp(periodic, s, length).displacement_px -
                                       rubber_stamp(own, s, length).displacement_px));
    EXPECT_LT(worst, 1e-9) << length << " px";
  }
  // Periodic in t (negative t too), unscaled on a short run.
  for (double s : {3.0, 500.5, 1021.0})
    EXPECT_NEAR(rubber_stamp(periodic, s - 2 * period, 10).displacement_px,
                rubber_stamp(periodic, s, 2000).displacement_px, 1e-9);
  EXPECT_THROW(synth.synthesize_period(2, CounterStream(1)), std::invalid_argument);
  EXPECT_THROW(synth.synthesize_period(std::numeric_limits<double>::infinity(), CounterStream(1)),
               std::invalid_argument);
}

TEST(OffsetSynthesis, DegenerateExamplesTerminateFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    const char* name;
    OffsetExample example;
    double value;  // every synthesized offset, or NaN: any finite
  };
  OffsetExample three{8, {{0.0, 1.0, 1.0, false}, {1.0, 3.0, 1.0, false}}};  // 3 samples < window
  std::vector<Case> cases{
      {"no offsets", {100, {}}, 0.0},
      {"only NaN offsets", {100, {{0.0, nan, 1.0, false}, {nan, 1.0, 1.0, false}}}, 0.0},
      {"one offset", {100, {{0.5, 2.0, 1.0, false}}}, 2.0},
      {"zero length", {0, {{0.0, 1.5, 1.0, false}, {1.0, 4.0, 1.0, false}}}, 1.5},
      {"NaN length", {nan, {{0.0, 1.5, 1.0, false}}}, 1.5},
      {"infinite length", {inf, {{0.0, 1.5, 1.0, false}}}, 1.5},
      {"constant", {400, {{0.0, -2.0, 1.0, false}, {1.0, -2.0, 1.0, false}}}, -2.0},
      {"shorter than the window", three, nan},
      {"as long as the window", {12, {{0.0, 0.0, 1.0, false}, {1.0, 3.0, 1.0, false}}}, nan},
      {"huge offsets", {400, {{0.0, -1e300, 1.0, false}, {0.3, 1e300, 1.0, false}, {1.0, 5.0, 1.0, false}}}, nan},
      {"NaN pressures", {40, {{0.0, 1.0, nan, false}, {1.0, 2.0, inf, true}}}, nan},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    OffsetSynthesizer synth(c.example);
    std::vector<double> y = synth.synthesize(kLongStroke, 1, c.name);
    OffsetExample list = synth.synthesize_example(100, 1, c.name);
    ASSERT_EQ(y.size(), 5001u);
    for (double v : y) {
      ASSERT_TRUE(std::isfinite(v) && std::abs(v) <= 1e6);
      if (!std::isnan(c.value)) {
        ASSERT_EQ(v, c.value);
      }
    }
    for (const StrokeOffset& o : list.offsets) {
      ASSERT_TRUE(std::isfinite(o.displacement_px) && std::isfinite(o.t));
      ASSERT_TRUE(o.pressure >= 0 && o.pressure <= 1);
    }
  }
  // Shorter than the window: the example rubber-stamped, 1 2 3 1 2 3 ...
  OffsetSynthesizer short_one(three);
  EXPECT_FALSE(short_one.is_markov());
  std::vector<double> y = short_one.synthesize(40, 1, "short");
  for (size_t k = 0; k < y.size(); ++k) EXPECT_EQ(y[k], 1.0 + double(k % 3)) << k;
  // Lengths: none, NaN and negative give one offset; past 1e7 offsets, a refusal.
  OffsetSynthesizer synth(sine(50));
  EXPECT_EQ(synth.synthesize(0, 1, "zero").size(), 1u);
  EXPECT_EQ(synth.synthesize(nan, 1, "nan").size(), 1u);
  EXPECT_EQ(synth.synthesize(-5, 1, "negative").size(), 1u);
  EXPECT_EQ(synth.synthesize(3, 1, "short").size(), 2u);
  EXPECT_EQ(synth.synthesize(4, 1, "one step").size(), 2u);
  EXPECT_THROW(synth.synthesize(inf, 1, "infinite"), std::invalid_argument);
  EXPECT_THROW(synth.synthesize(1e9, 1, "too long"), std::invalid_argument);
  // More than 2048 states: a refusal, not hours of work.
  EXPECT_THROW(OffsetSynthesizer(sine(50, 200)), std::invalid_argument);
}

// Controls: the checks above are able to fail. Uniform transitions (rho huge) lose the
// autocorrelation; a window of 1 cannot tell a sine's rising half from its falling half,
// which scrambles its period.
TEST(OffsetSynthesis, ControlsFailTheChecks) {
  OffsetSynthesisOptions uniform;
  uniform.rho_factor = 1e12;
  OffsetSynthesisOptions no_window;
  no_window.window = 1;
  for (const OffsetExample& e : {sine(50), sawtooth(), random_walk()}) {
    Deviation d = deviation(OffsetSynthesizer(e, uniform), e, 1);
    std::printf("  uniform transitions: max |r_k diff| %.3f\n", d.autocorrelation);
    EXPECT_FALSE(within(d, kWalkBound));
  }
  OffsetSynthesizer scrambled(sine(50), no_window);
  Deviation d = deviation(scrambled, sine(50), 1);
  Stats s = stats(scrambled.synthesize(kLongStroke, 1, "period"), 40);
  double measured = 4 * dominant_period(s.r);
  std::printf("  window of 1, sine of period 50 px: max |r_k diff| %.3f, dominant period %.3f px\n", d.autocorrelation,
              measured);
  EXPECT_FALSE(within(d, kPeriodicBound));
  EXPECT_GT(std::abs(measured - 50), 1.0);
}

}  // namespace
}  // namespace plumbago
