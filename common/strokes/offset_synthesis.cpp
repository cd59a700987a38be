#include "common/strokes/offset_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace plumbago {

namespace {

constexpr size_t kMaxStates = 2048;     // states x states costs are held while building
constexpr double kMaxOffsets = 1e7;     // refuse syntheses (and resamplings) longer than this
constexpr double kDroppedWeight = 1e-12;  // row weights below this (row max = 1) are dropped
constexpr double kMaxDisplacement = 1e6;  // px: displacements are clamped to +-this
constexpr double kMaxP = 8;               // with the clamp, (2e6)^8 x 1e3 x states^2 stays finite
constexpr double kInf = std::numeric_limits<double>::infinity();

void check_step(double step_px, const char* who) {
  if (!(std::isfinite(step_px) && step_px > 0))
    throw std::invalid_argument(std::string(who) + ": step " + std::to_string(step_px) + " px is not positive and finite");
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
  // 2. y with its separators; pos_of[state] = position of the state in y.
  std::vector<double> y{0.0};
  std::vector<char> separator{1};
  std::vector<ptrdiff_t> pos_of;
  for (const OffsetExample& e : examples) {
    Resampled r = resample(e, options_.step_px);
    if (r.displacement.empty()) continue;
    if (values_.size() + r.displacement.size() > kMaxStates)
      throw std::invalid_argument("OffsetSynthesizer: more than " + std::to_string(kMaxStates) + " states (" +
                                  std::to_string(kMaxStates * options_.step_px) + " px of examples)");
    starts_.push_back(values_.size());
    for (size_t k = 0; k < r.displacement.size(); ++k) {
      pos_of.push_back(ptrdiff_t(y.size()));
      y.push_back(r.displacement[k]);
      separator.push_back(0);
      values_.push_back(r.displacement[k]);
      pressures_.push_back(r.pressure[k]);
    }
    y.push_back(0.0);
    separator.push_back(1);
  }
  const size_t n = values_.size();
  if (n == 0) return;
  successor_.resize(n);
  for (size_t e = 0; e < starts_.size(); ++e) {
    size_t end = e + 1 < starts_.size() ? starts_[e + 1] : n;
    for (size_t s = starts_[e]; s < end; ++s) successor_[s] = s + 1 < end ? s + 1 : starts_[(e + 1) % starts_.size()];
  }

  // 3.-4. C_ij = (D'_{i+1,j})^p, +inf where forbidden.
  const int m = options_.window;
  const double w = 1.0 / m;
  std::vector<double> cost(n * n);
  std::vector<size_t> sources(n, 0);  // allowed transitions into each state
  for (size_t i = 0; i < n; ++i) {
    bool any = false;
    for (size_t j = 0; j < n; ++j) {
      double sum = 0;
      bool forbidden = false;
      for (int k = 0; k < m; ++k) {
        ptrdiff_t a = pos_of[i] + 1 - k, b = pos_of[j] - k;
        if (a < 0 || separator[a]) {
          if (k == 0) continue;  // i ends its example: no natural successor to compare
          break;                 // the source's window ends: the rest is 0
        }
        if (b < 0 || separator[b]) {
          forbidden = true;  // K: the target's window ends before the source's
          break;
        }
        sum += std::abs(y[a] - y[b]);
      }
      double c = forbidden ? kInf : std::pow(w * sum, options_.p);
      cost[i * n + j] = c;
      if (!forbidden) {
        any = true;
        ++sources[j];
      }
    }
    if (!any) return;  // a state with no way on: rubber-stamp instead
  }
  markov_ = true;

  // 5. Q-learning. D''^(t) = C + alpha V^(t-1) (V^(-1) = 0), V^(t)_j = min_k D''^(t)_jk, so
  // the change from D''^(t) to D''^(t+1) is sum_j sources_j alpha |V^(t)_j - V^(t-1)_j|.
  const double alpha = options_.alpha;
  std::vector<double> v_prev(n, 0.0), v(n);
  for (iterations_ = 0; iterations_ < options_.max_iterations;) {
    for (size_t j = 0; j < n; ++j) {
      double best = kInf;
      const double* row = &cost[j * n];
      for (size_t k = 0; k < n; ++k) best = std::min(best, row[k] + alpha * v_prev[k]);
      v[j] = best;  // finite: every row has an allowed entry
    }
    double change = 0;
    for (size_t j = 0; j < n; ++j) change += double(sources[j]) * alpha * std::abs(v[j] - v_prev[j]);
    v_prev.swap(v);
    ++iterations_;
    last_change_ = change;
    if (change < options_.total_change) break;
  }

  // 6. rho from the nonzero allowed entries of D'' = C + alpha v_prev.
  double total = 0;
  size_t count = 0;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) {
      double d = cost[i * n + j] + alpha * v_prev[j];
      if (std::isfinite(d) && d > 0) {
        total += d;
        ++count;
      }
    }
  double mean = count ? total / double(count) : 0.0;
  rho_ = options_.rho_factor * mean;
  if (!(std::isfinite(rho_) && rho_ > 0)) rho_ = 1;

  rows_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    double low = kInf;
    for (size_t j = 0; j < n; ++j) low = std::min(low, cost[i * n + j] + alpha * v_prev[j]);
    Row& row = rows_[i];
    double cumulative = 0;
    for (size_t j = 0; j < n; ++j) {
      double d = cost[i * n + j] + alpha * v_prev[j];
      if (!std::isfinite(d)) continue;
      double weight = std::exp(-(d - low) / rho_);
      if (!(weight >= kDroppedWeight)) continue;
      cumulative += weight;
      row.to.push_back(uint32_t(j));
      row.cdf.push_back(cumulative);
    }
  }
}

size_t OffsetSynthesizer::next_state(size_t i, Rng& rng) const {
  if (!markov_) return successor_[i];
  const Row& row = rows_[i];
  double u = rng.uniform() * row.cdf.back();
  size_t k = size_t(std::upper_bound(row.cdf.begin(), row.cdf.end(), u) - row.cdf.begin());
  return row.to[std::min(k, row.to.size() - 1)];
}

std::vector<size_t> OffsetSynthesizer::walk(size_t n, Rng& rng) const {
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
  Rng rng(seed, "offset-synthesis/" + std::string(name));
  std::vector<size_t> states = walk(n, rng);
  std::vector<double> out(n, 0.0);
  for (size_t k = 0; k < states.size(); ++k) out[k] = values_[states[k]];
  return out;
}

OffsetExample OffsetSynthesizer::synthesize_example(double length_px, uint32_t seed, std::string_view name) const {
  const double step = options_.step_px;
  double length = std::max(length_px > 0 ? length_px : 0.0, 1.0);  // NaN: 1; infinity: refused below
  size_t n = offset_count(length, step);
  Rng rng(seed, "offset-synthesis/" + std::string(name));
  std::vector<size_t> states = walk(n, rng);
  auto value = [&](size_t k) { return states.empty() ? 0.0 : values_[states[k]]; };
  auto pressure = [&](size_t k) { return states.empty() ? 1.0 : pressures_[states[k]]; };
  OffsetExample out;
  out.length_px = length;
  for (size_t k = 0; k < n && double(k) * step < length * (1 - 1e-12); ++k)
    out.offsets.push_back({double(k) * step / length, value(k), pressure(k), false});
  double at = length / step;
  size_t k0 = std::min(size_t(std::floor(at)), n - 1);
  double f = k0 + 1 < n ? at - double(k0) : 0.0;
  size_t k1 = std::min(k0 + 1, n - 1);
  out.offsets.push_back({1.0, std::lerp(value(k0), value(k1), f), std::lerp(pressure(k0), pressure(k1), f), false});
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

OffsetExample synthesize_offset_example(const OffsetExample& e, double length_px, uint32_t seed, std::string_view name) {
  return OffsetSynthesizer(e).synthesize_example(length_px, seed, name);
}

}  // namespace plumbago
