// Synthesis of stroke offsets by example (Kalnins et al. 2002 §5.3 and
// Appendix A, which follows the "video textures" of Schödl et al. 2000): a Markov chain
// whose states are the offsets of a few example strokes, resampled every 4 px, and whose
// transitions favour the offsets whose neighbourhood looks like the natural next one.
//
// 1. Resampling. An example (t in [0, 1], displacement px, over L_drawn px) is sampled at
//    arc lengths s_k = k x 4 px, k = 0 .. floor(L_drawn / 4), i.e. t_k = s_k / L_drawn, the
//    displacement (and pressure) interpolated linearly in t between its offsets and held
//    before the first and after the last.
// 2. The vector y: the examples' samples concatenated, each example preceded and followed
//    by a "separator" (reading below), positions 0 .. M-1. Every non-separator position is
//    a state; a separator never is (a transition into one is forbidden).
// 3. Distances (Appendix A): D_ab = K (forbidden) when y_b is a separator and y_a is not,
//    0 when y_a is a separator, |y_a - y_b| otherwise; filtered with the window of m = 4
//    taps, weights w_k = 1/4:  D'_ab = sum_{k=0..3} w_k D_{a-k, b-k}, where a window ends at
//    its example's start (reading below).
// 4. The cost of going from state i to state j (j takes the place of i's natural successor
//    i+1) is D'_{i+1, j}, raised to the power p = 2:  C_ij = (D'_{i+1,j})^p.
// 5. Q-learning (future costs, so that the chain avoids windows that lead to dead ends):
//      D''_ij <- C_ij + alpha min_k D''_jk,   D'' initialized to C, alpha = 0.999,
//    repeated until the total change sum_ij |D''_new - D''_old| is below 10, at most 100
//    times.
// 6. Transitions: P_ij proportional to exp(-D''_ij / rho), rho = 0.01 x the mean of D''
//    over its nonzero (and allowed) entries; forbidden transitions have probability 0.
// 7. Synthesis: a random example's first state, then n-1 transitions, one offset per 4 px.
//
// Readings, where the paper is vague or its formula taken literally would misbehave:
//   - Indexing of D'' (5., 6.): the appendix writes P_ij ~ exp(-D''_{i+1,j}) and
//     D''_ij <- (D'_ij)^p + alpha min_k D''_jk. Read literally, the future cost added to
//     the transition into j would be that of the transition out of j-1 (row j of D'' is
//     read by P as the row of state j-1). Here D''_ij is indexed by the transition
//     itself, from state i to state j, with the shift applied once, in C_ij = D'_{i+1,j}^p;
//     so P_ij ~ exp(-D''_ij / rho) with this D'' is the paper's exp(-D''_{i+1,j} / rho),
//     and min_k D''_jk is the cheapest transition out of j, as in Schödl et al. 2000.
//   - Window: Kalnins et al.'s (2002, §4.3, App. A) window of 4 with weights 1/4 (k = 0..3, sum 1). The appendix's
//     "m = 4, w_i = 1/m, k = 0..m" would be 5 taps summing to 5/4.
//   - Separators and windows: one separator also precedes the first example, so that all
//     examples are alike (with the appendix's "out-of-range entries are zero" the first
//     example's first samples would be cheap targets whose window is mostly missing), and
//     a window ends at its example's start: the terms of D' past the separator in the
//     source's window (row a) are 0, and a term whose target position (b - k) is a
//     separator, or out of range, while the source's is a sample is K. (Read literally the
//     appendix would compare, past a separator, the tail of the previous example, and give
//     K to a separator against a separator, which would forbid even the natural step from
//     an example's first sample to its second.) The term k = 0 of a state that ends its
//     example (its row a = i+1 is the separator) is 0 and its window goes on, so the jump
//     out of an example's last state is chosen by the 3 samples before it. Consequences:
//     every state that has a natural successor reaches it at cost 0; sample r < m-1 of an
//     example is reachable only from states nearer their own example's start (r' < r),
//     its first sample only by starting there.
//   - K = 10^4 is realized as "forbidden": probability exactly 0, left out of the minima
//     of 5. and of the mean of 6. (in the appendix rho comes from entries "greater than
//     zero and less than the magnitude of the largest example offset", i.e. not K's).
//   - rho: when D'' has no nonzero allowed entry (a constant example) rho = 1: every
//     allowed transition is then equally likely, and all give the same offset.
//   - Total change (5.): the sum over allowed entries, in px^p.
//   - Breaks (pen_up) are not synthesized ("the synthesis algorithm does not yet handle
//     breaks or backtracking"): resampling interpolates across a lift and the output has
//     no breaks. The pressure rides along: a state's pressure is its sample's.
//   - Degenerate examples: offsets whose t or displacement is not finite are dropped;
//     displacements are clamped to +-1e6 px (validate_stroke_style allows +-1000), so that
//     every cost stays finite (p is refused past 8); pressures not finite count as 1, the
//     others are clamped to [0, 1]. An example with no
//     offset left gives no state; if no example has a state, every synthesized offset is
//     0 (pressure 1). An example whose length is not finite or not positive gives one
//     sample, its offset at t = 0. If some state has no allowed transition at all (no
//     example has m samples or more), the chain is not built: the synthesis rubber-stamps
//     the examples instead (their samples in turn, from a random example's start,
//     repeating).
//   - Row weights exp(-(D''_ij - min_j D''_ij) / rho) under 1e-12 are dropped (the
//     probability each carried is below 1e-12 x the row's count).
//   - Seeding: a counter-based stream (common/util/random.hpp CounterStream), keyed by the
//     seed and "offset-synthesis/" + name, so that a stroke's name used to seed something
//     else does not give the same numbers, or given its key (a stroke run's: integers only,
//     common/strokes/stroke.hpp RunStyles).
//   - Size: at most 2048 states (8192 px of examples at 4 px); more throws
//     std::invalid_argument (the model holds a states x states matrix while it is built).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "common/strokes/stroke_style.hpp"
#include "common/util/random.hpp"

namespace plumbago {

// Kalnins et al.'s (2002, §4.3, App. A) parameters; the defaults are Appendix A's.
struct OffsetSynthesisOptions {
  double step_px = 4;        // resampling step (1.)
  int window = 4;            // m taps of weight 1/m (3.)
  double p = 2;              // exponent of the cost (4.), in (0, 8]
  double alpha = 0.999;      // Q-learning discount (5.)
  double total_change = 10;  // Q-learning stops when the total change is below this
  int max_iterations = 100;  // ... or after this many iterations
  double rho_factor = 0.01;  // rho = rho_factor x mean nonzero D'' (6.)
};

// The example's displacements every step_px of its length (1.), floor(L_drawn / step_px)
// + 1 of them (none for an example with no finite offset). Throws std::invalid_argument
// when step_px is not positive and finite, or for more than 1e7 samples.
std::vector<double> resample_offsets(const OffsetExample& e, double step_px = 4);

// The Markov chain of 2.-6., built once for a set of examples; synthesizing from it is cheap.
// The constructors throw std::invalid_argument for options out of their ranges and for
// more than 2048 states.
class OffsetSynthesizer {
 public:
  explicit OffsetSynthesizer(const OffsetExample& example, const OffsetSynthesisOptions& options = {});
  explicit OffsetSynthesizer(std::span<const OffsetExample> examples, const OffsetSynthesisOptions& options = {});

  // n states of the chain (indices into values()), from a random example's start: one
  // rng.uniform() for the start and one per transition, so a longer walk begins like a
  // shorter one. Empty when there is no state.
  std::vector<size_t> walk(size_t n, CounterStream& rng) const;

  // The displacements (px), one every step_px: ceil(length_px / step_px) + 1 of them
  // (the first at 0, the last at or past length_px); a length not positive (or NaN) gives
  // one. Seeded by the seed and "offset-synthesis/" + name. Throws std::invalid_argument
  // for more than 1e7 offsets (an infinite length included).
  std::vector<double> synthesize(double length_px, uint32_t seed, std::string_view name) const;

  // The same synthesis as an offset list over a run of length_px, for rubber_stamp and
  // base_stroke: length_px = max(length_px, 1) (validate_stroke_style's least L_drawn;
  // rubber_stamp then scales by min(L / L_drawn, 1) = 1 for a run of that length),
  // offset k at t = k step / length_px while that is below 1, then one at t = 1
  // interpolated between the last two synthesized (the offsets of
  // synthesize(max(length_px, 1), seed, name)); pressures from the states; no breaks. It
  // does not repeat (OffsetExample::repeats false): a run a little longer holds its last offset.
  OffsetExample synthesize_example(double length_px, uint32_t seed, std::string_view name) const;
  // The same from a given stream.
  OffsetExample synthesize_example(double length_px, CounterStream stream) const;
  // The walk from `stream` as a periodic example of period_px (a brush path's along its
  // brush parameter: common/strokes/coherent_silhouettes.hpp 5.): offset k at t = k step /
  // period_px while that is below 1, the last one running into the first; it repeats and
  // does not scale. On [0, L] it is synthesize_example(L, stream)'s, L <= period_px - step. Throws
  // std::invalid_argument where period_px is not finite, below step or over 1e7 offsets.
  OffsetExample synthesize_period(double period_px, CounterStream stream) const;

  // Inspection, for tests.
  size_t state_count() const { return values_.size(); }
  const std::vector<double>& values() const { return values_; }  // displacement per state
  const std::vector<double>& pressures() const { return pressures_; }
  bool is_markov() const { return markov_; }  // false: rubber-stamp fallback (or no state)
  double rho() const { return rho_; }
  int iterations() const { return iterations_; }       // Q-learning iterations run
  double last_change() const { return last_change_; }  // total change of the last one
  // P_ij (0 for a forbidden or dropped transition); only when is_markov().
  double probability(size_t i, size_t j) const;
  const OffsetSynthesisOptions& options() const { return options_; }
  // The chain as walk() reads it (the GPU's copy: gpu/strokes/run_styles.hpp): each example's
  // first state, each state's natural successor (the rubber-stamp fallback) and, when
  // is_markov(), row i's allowed targets and their cumulative weights.
  const std::vector<size_t>& starts() const { return starts_; }
  const std::vector<size_t>& successors() const { return successor_; }
  const std::vector<uint32_t>& targets(size_t i) const { return rows_.at(i).to; }
  const std::vector<double>& cumulative(size_t i) const { return rows_.at(i).cdf; }

 private:
  struct Row {
    std::vector<uint32_t> to;  // allowed targets, increasing
    std::vector<double> cdf;   // cumulative weights, last = total
  };
  size_t next_state(size_t i, CounterStream& rng) const;

  OffsetSynthesisOptions options_;
  std::vector<double> values_, pressures_;
  std::vector<size_t> starts_;     // first state of each example that has one
  std::vector<size_t> successor_;  // fallback: the next state, cyclically over the examples
  std::vector<Row> rows_;
  bool markov_ = false;
  double rho_ = 1;
  int iterations_ = 0;
  double last_change_ = 0;
};

// One-call forms of OffsetSynthesizer::synthesize / synthesize_example with the default options.
std::vector<double> synthesize_offsets(const OffsetExample& e, double length_px, uint32_t seed, std::string_view name);
OffsetExample synthesize_offset_example(const OffsetExample& e, double length_px, uint32_t seed, std::string_view name);

}  // namespace plumbago
