#include "common/strokes/offset_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace plumbago {

namespace {

constexpr size_t kMaxStates = 2048;       // states x states costs are held while building
constexpr double kMaxOffsets = 1e7;       // refuse syntheses (and resamplings) longer than this
constexpr double kDroppedWeight = 1e-12;  // row weights below this (row max = 1) are dropped
constexpr double kMaxDisplacement = 1e6;  // px: displacements are clamped to +-this
constexpr double kMaxP = 8;               // with the clamp, (2e6)^8 x 1e3 x states^2 stays finite
constexpr double kInf = std::numeric_limits<double>::infinity();

void check_step(double step_px, const char* who) {
  if (!(std::isfinite(step_px) && step_px > 0))
    throw std::invalid_argument(std::string(who) + ": step " + std::to_string(step_px) +
                                " px is not positive and finite");
}

void check_options(const OffsetSynthesisOptions& o) {
  check_step(o.step_px, "OffsetSynthesizer");
  if (o.window < 1) throw std::invalid_argument("OffsetSynthesizer: window must be at least 1");
  if (!(o.p > 0 && o.p <= kMaxP)) throw std::invalid_argument("OffsetSynthesizer: p must be in (0, 8]");
  if (!(o.alpha >= 0 && o.alpha < 1)) throw std::invalid_argument("OffsetSynthesizer: alpha must be in [0, 1)");
  if (!(o.total_change >= 0)) throw std::invalid_argument("OffsetSynthesizer: total_change must not be negative");
  if (o.max_iterations < 0) throw std::invalid_argument("OffsetSynthesizer: max_iterations must not be negative");
  if (!(std::isfinite(o.rho_factor) && o.rho_factor > 0))
    throw std::invalid_argument("OffsetSynthesizer: rho_factor must be positive and finite");
}

// Displacement and pressure every step px (header, 1.).
struct Resampled {
  std::vector<double> displacement, pressure;
};

Resampled resample(const OffsetExample& e, double step) {
  std::vector<StrokeOffset> o;
  for (const StrokeOffset& x : e.offsets)
    if (std::isfinite(x.t) && std::isfinite(x.displacement_px)) {
      StrokeOffset c = x;
      c.displacement_px = std::clamp(c.displacement_px, -kMaxDisplacement, kMaxDisplacement);
      c.pressure = std::isfinite(c.pressure) ? std::clamp(c.pressure, 0.0, 1.0) : 1.0;
      o.push_back(c);
    }
  std::stable_sort(o.begin(), o.end(), [](const StrokeOffset& a, const StrokeOffset& b) { return a.t < b.t; });
  Resampled r;
  if (o.empty()) return r;
  double length = std::isfinite(e.length_px) && e.length_px > 0 ? e.length_px : 0.0;
  double q = length / step;
  if (q > kMaxOffsets) throw std::invalid_argument("resample_offsets: more than 1e7 samples");
  size_t n = size_t(std::floor(q * (1 + 1e-12))) + 1;
  for (size_t k = 0; k < n; ++k) {
    double t = length > 0 ? std::min(double(k) * step / length, 1.0) : 0.0;
    auto up = std::upper_bound(o.begin(), o.end(), t, [](double x, const StrokeOffset& s) { return x < s.t; });
    if (up == o.begin()) {
      r.displacement.push_back(o.front().displacement_px);
      r.pressure.push_back(o.front().pressure);
    } else if (up == o.end()) {
      r.displacement.push_back(o.back().displacement_px);
      r.pressure.push_back(o.back().pressure);
    } else {
      const StrokeOffset& a = *(up - 1);
      const StrokeOffset& b = *up;  // b.t > t >= a.t
      double f = (t - a.t) / (b.t - a.t);
      r.displacement.push_back(std::lerp(a.displacement_px, b.displacement_px, f));
      r.pressure.push_back(std::lerp(a.pressure, b.pressure, f));
    }
  }
  return r;
}

// ceil(length / step) + 1 offsets; one for a length not positive; refused past 1e7.
size_t offset_count(double length_px, double step) {
  if (!(length_px > 0)) return 1;
  double q = length_px / step;
  if (!(q <= kMaxOffsets)) throw std::invalid_argument("synthesize_offsets: more than 1e7 offsets");
  return size_t(std::ceil(q * (1 - 1e-12))) + 1;
}

// 2. The vector y: the examples' samples (1.) concatenated, a separator before and after
// each example. Every sample is a state, numbered in the order of y.
struct StateSequence {
  std::vector<double> y{0.0};
  std::vector<char> separator{1};
  std::vector<ptrdiff_t> pos_of;          // position in y of each state
  std::vector<double> values, pressures;  // displacement and pressure of each state
  std::vector<size_t> starts;             // first state of each example that has one
};

StateSequence concatenate_examples(std::span<const OffsetExample> examples, double step) {
  StateSequence q;
  for (const OffsetExample& e : examples) {
    Resampled r = resample(e, step);
    if (r.displacement.empty()) continue;
    if (q.values.size() + r.displacement.size() > kMaxStates)
      throw std::invalid_argument("OffsetSynthesizer: more than " + std::to_string(kMaxStates) + " states (" +
                                  std::to_string(kMaxStates * step) + " px of examples)");
    q.starts.push_back(q.values.size());
    for (size_t k = 0; k < r.displacement.size(); ++k) {
      q.pos_of.push_back(ptrdiff_t(q.y.size()));
      q.y.push_back(r.displacement[k]);
      q.separator.push_back(0);
      q.values.push_back(r.displacement[k]);
      q.pressures.push_back(r.pressure[k]);
    }
    q.y.push_back(0.0);
    q.separator.push_back(1);
  }
  return q;
}

// The rubber stamp's next state (when there is no chain): the next sample of the example,
// after its last the first of the next example, cyclically.
std::vector<size_t> natural_successors(const std::vector<size_t>& starts, size_t n) {
  std::vector<size_t> successor(n);
  for (size_t e = 0; e < starts.size(); ++e) {
    size_t end = e + 1 < starts.size() ? starts[e + 1] : n;
    for (size_t s = starts[e]; s < end; ++s) successor[s] = s + 1 < end ? s + 1 : starts[(e + 1) % starts.size()];
  }
  return successor;
}

// 3. m D'_{i+1,j} (Appendix A, windows ended by the separators as read in the header):
// sum_{k<m} |y_a - y_b| for a = pos(i) + 1 - k, b = pos(j) - k; nothing for K (forbidden).
std::optional<double> window_distance(const StateSequence& q, size_t i, size_t j, int m) {
  double sum = 0;
  for (int k = 0; k < m; ++k) {
    ptrdiff_t a = q.pos_of[i] + 1 - k, b = q.pos_of[j] - k;
    if (a < 0 || q.separator[a]) {
      if (k == 0) continue;  // i ends its example: no natural successor to compare
      break;                 // the source's window ends: the rest is 0
    }
    if (b < 0 || q.separator[b]) return std::nullopt;  // K: the target's window ends before the source's
    sum += std::abs(q.y[a] - q.y[b]);
  }
  return sum;
}

struct TransitionCosts {
  std::vector<double> cost;     // C_ij at i n + j, +inf where forbidden
  std::vector<size_t> sources;  // allowed transitions into each state
};

// 4. C_ij = (D'_{i+1,j})^p (Appendix A). Nothing when some state has no allowed
// transition at all: then there is no chain.
std::optional<TransitionCosts> transition_costs(const StateSequence& q, const OffsetSynthesisOptions& o) {
  const size_t n = q.pos_of.size();
  const int m = o.window;
  const double w = 1.0 / m;
  TransitionCosts t{std::vector<double>(n * n), std::vector<size_t>(n, 0)};
  for (size_t i = 0; i < n; ++i) {
    bool any = false;
    for (size_t j = 0; j < n; ++j) {
      std::optional<double> sum = window_distance(q, i, j, m);
      t.cost[i * n + j] = sum ? std::pow(w * *sum, o.p) : kInf;
      if (sum) {
        any = true;
        ++t.sources[j];
      }
    }
    if (!any) return std::nullopt;
  }
  return t;
}

struct FutureCosts {
  std::vector<double> v;  // V_j = min_k D''_jk of the last iteration
  int iterations = 0;
  double last_change = 0;
};

// 5. Q-learning (Appendix A). D''^(t) = C + alpha V^(t-1) (V^(-1) = 0), V^(t)_j = min_k
// D''^(t)_jk, so the change from D''^(t) to D''^(t+1) is sum_j sources_j alpha |V^(t)_j -
// V^(t-1)_j|; until it is below total_change, at most max_iterations times.
FutureCosts q_learning(const TransitionCosts& t, const OffsetSynthesisOptions& o) {
  const size_t n = t.sources.size();
  const double alpha = o.alpha;
  FutureCosts f{std::vector<double>(n, 0.0)};
  std::vector<double> v(n);
  while (f.iterations < o.max_iterations) {
    for (size_t j = 0; j < n; ++j) {
      double best = kInf;
      const double* row = &t.cost[j * n];
      for (size_t k = 0; k < n; ++k) best = std::min(best, row[k] + alpha * f.v[k]);
      v[j] = best;  // finite: every row has an allowed entry
    }
    double change = 0;
    for (size_t j = 0; j < n; ++j) change += double(t.sources[j]) * alpha * std::abs(v[j] - f.v[j]);
    f.v.swap(v);
    ++f.iterations;
    f.last_change = change;
    if (change < o.total_change) break;
  }
  return f;
}

// D''_ij = C_ij + alpha V_j (5.).
double total_cost(const TransitionCosts& t, const FutureCosts& f, double alpha, size_t i, size_t j) {
  return t.cost[i * f.v.size() + j] + alpha * f.v[j];
}

// 6. rho = rho_factor x the mean of D'' over its nonzero allowed entries; 1 when that is
// not positive and finite (no such entry).
double temperature(const TransitionCosts& t, const FutureCosts& f, const OffsetSynthesisOptions& o) {
  const size_t n = f.v.size();
  double total = 0;
  size_t count = 0;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) {
      double d = total_cost(t, f, o.alpha, i, j);
      if (std::isfinite(d) && d > 0) {
        total += d;
        ++count;
      }
    }
  double mean = count ? total / double(count) : 0.0;
  double rho = o.rho_factor * mean;
  return std::isfinite(rho) && rho > 0 ? rho : 1;
}

// 6. Row i of P_ij ~ exp(-D''_ij / rho), as the cumulative weights exp(-(D''_ij - min_j
// D''_ij) / rho) of its allowed targets j (increasing), weights below kDroppedWeight dropped.
void transition_row(const TransitionCosts& t, const FutureCosts& f, double alpha, double rho, size_t i,
                    std::vector<uint32_t>& to, std::vector<double>& cdf) {
  const size_t n = f.v.size();
  double low = kInf;
  for (size_t j = 0; j < n; ++j) low = std::min(low, total_cost(t, f, alpha, i, j));
  double cumulative = 0;
  for (size_t j = 0; j < n; ++j) {
    double d = total_cost(t, f, alpha, i, j);
    if (!std::isfinite(d)) continue;
    double weight = std::exp(-(d - low) / rho);
    if (!(weight >= kDroppedWeight)) continue;
    cumulative += weight;
    to.push_back(uint32_t(j));
    cdf.push_back(cumulative);
  }
}

}  // namespace

std::vector<double> resample_offsets(const OffsetExample& e, double step_px) {
  check_step(step_px, "resample_offsets");
  return resample(e, step_px).displacement;
}

OffsetSynthesizer::OffsetSynthesizer(const OffsetExample& example, const OffsetSynthesisOptions& options)
    : OffsetSynthesizer(std::span<const OffsetExample>(&example, 1), options) {}

OffsetSynthesizer::OffsetSynthesizer(std::span<const OffsetExample> examples, const OffsetSynthesisOptions& options)
    : options_(options) {
  check_options(options_);
  StateSequence states = concatenate_examples(examples, options_.step_px);
  values_ = std::move(states.values);
  pressures_ = std::move(states.pressures);
  starts_ = std::move(states.starts);
  const size_t n = values_.size();
  if (n == 0) return;
  successor_ = natural_successors(starts_, n);
  std::optional<TransitionCosts> costs = transition_costs(states, options_);
  if (!costs) return;  // a state with no way on: rubber-stamp instead
  markov_ = true;
  FutureCosts future = q_learning(*costs, options_);
  iterations_ = future.iterations;
  last_change_ = future.last_change;
  rho_ = temperature(*costs, future, options_);
  rows_.resize(n);
  for (size_t i = 0; i < n; ++i) transition_row(*costs, future, options_.alpha, rho_, i, rows_[i].to, rows_[i].cdf);
}

size_t OffsetSynthesizer::next_state(size_t i, CounterStream& rng) const {
  if (!markov_) return successor_[i];
  const Row& row = rows_[i];
  double u = rng.uniform() * row.cdf.back();
  size_t k = size_t(std::upper_bound(row.cdf.begin(), row.cdf.end(), u) - row.cdf.begin());
  return row.to[std::min(k, row.to.size() - 1)];
}

std::vector<size_t> OffsetSynthesizer::walk(size_t n, CounterStream& rng) const {
  std::vector<size_t> out;
  if (n == 0 || values_.empty()) return out;
  out.reserve(n);
  size_t e = std::min(size_t(rng.uniform() * double(starts_.size())), starts_.size() - 1);
  out.push_back(starts_[e]);
  while (out.size() < n) out.push_back(next_state(out.back(), rng));
  return out;
}

std::vector<double> OffsetSynthesizer::synthesize(double length_px, uint32_t seed, std::string_view name) const {
  size_t n = offset_count(length_px, options_.step_px);
  CounterStream rng(named_key(seed, "offset-synthesis/" + std::string(name)));
  std::vector<size_t> states = walk(n, rng);
  std::vector<double> out(n, 0.0);
  for (size_t k = 0; k < states.size(); ++k) out[k] = values_[states[k]];
  return out;
}

OffsetExample OffsetSynthesizer::synthesize_example(double length_px, uint32_t seed, std::string_view name) const {
  return synthesize_example(length_px, CounterStream(named_key(seed, "offset-synthesis/" + std::string(name))));
}

OffsetExample OffsetSynthesizer::synthesize_example(double length_px, CounterStream rng) const {
  const double step = options_.step_px;
  double length = std::max(length_px > 0 ? length_px : 0.0, 1.0);  // NaN: 1; infinity: refused below
  size_t n = offset_count(length, step);
  std::vector<size_t> states = walk(n, rng);
  auto value = [&](size_t k) { return states.empty() ? 0.0 : values_[states[k]]; };
  auto pressure = [&](size_t k) { return states.empty() ? 1.0 : pressures_[states[k]]; };
  OffsetExample out;
  out.length_px = length;
  out.repeats = false;  // made for this length
  for (size_t k = 0; k < n && double(k) * step < length * (1 - 1e-12); ++k)
    out.offsets.push_back({double(k) * step / length, value(k), pressure(k), false});
  double at = length / step;
  size_t k0 = std::min(size_t(std::floor(at)), n - 1);
  double f = k0 + 1 < n ? at - double(k0) : 0.0;
  size_t k1 = std::min(k0 + 1, n - 1);
  out.offsets.push_back({1.0, std::lerp(value(k0), value(k1), f), std::lerp(pressure(k0), pressure(k1), f), false});
  return out;
}

OffsetExample OffsetSynthesizer::synthesize_period(double period_px, CounterStream rng) const {
  const double step = options_.step_px;
  if (!(period_px >= step) || !std::isfinite(period_px))
    throw std::invalid_argument("synthesize_period: the period must be finite and at least one step");
  size_t n = offset_count(period_px, step) - 1;  // k step < period_px
  std::vector<size_t> states = walk(n, rng);
  OffsetExample out;
  out.length_px = period_px;
  out.scales = false;
  for (size_t k = 0; k < n; ++k)
    out.offsets.push_back({double(k) * step / period_px, states.empty() ? 0.0 : values_[states[k]],
                           states.empty() ? 1.0 : pressures_[states[k]], false});
  return out;
}

double OffsetSynthesizer::probability(size_t i, size_t j) const {
  if (!markov_ || i >= rows_.size()) return 0;
  const Row& row = rows_[i];
  auto it = std::lower_bound(row.to.begin(), row.to.end(), uint32_t(j));
  if (it == row.to.end() || *it != j) return 0;
  size_t k = size_t(it - row.to.begin());
  double weight = row.cdf[k] - (k ? row.cdf[k - 1] : 0.0);
  return weight / row.cdf.back();
}

std::vector<double> synthesize_offsets(const OffsetExample& e, double length_px, uint32_t seed, std::string_view name) {
  return OffsetSynthesizer(e).synthesize(length_px, seed, name);
}

OffsetExample synthesize_offset_example(const OffsetExample& e, double length_px, uint32_t seed,
                                        std::string_view name) {
  return OffsetSynthesizer(e).synthesize_example(length_px, seed, name);
}

}  // namespace plumbago
