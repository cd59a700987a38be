#include "experiments/temporal_coherence/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace plumbago::temporal_coherence {

double slide(const TrackedRun& from, const TrackedSample& sample, const TrackedRun& to, const Landing& landing) {
  double d = landing.s - sample.s;
  if (from.closed && to.closed) d = std::remainder(d, to.length_px);
  return std::abs(d);
}

namespace {

// Per stroke of carry's `from` frame: true when none of its samples landed.
std::vector<bool> unmatched(const Landings& landings) {
  std::vector<bool> out;
  for (const auto& run : landings)
    out.push_back(std::none_of(run.begin(), run.end(), [](const auto& l) { return l.has_value(); }));
  return out;
}

}  // namespace

void accumulate(PairMeasures& into, const PairMeasures& m) {
  into.runs_prev += m.runs_prev, into.runs_next += m.runs_next, into.died += m.died, into.born += m.born;
  into.length_prev_px += m.length_prev_px, into.length_next_px += m.length_next_px;
  into.died_px += m.died_px, into.born_px += m.born_px;
  into.samples += m.samples, into.matched += m.matched;
  for (auto field : {&PairMeasures::slide_px, &PairMeasures::alpha_change, &PairMeasures::width_change_px,
                     &PairMeasures::offset_change_px, &PairMeasures::stretch})
    (into.*field).insert((into.*field).end(), (m.*field).begin(), (m.*field).end());
}

std::vector<std::pair<std::string, PairMeasures>> pair_measures(const FrameStrokes& prev, const FrameStrokes& next,
                                                                const MatchParams& params) {
  Landings forward = carry(prev, next, params), backward = carry(next, prev, params);
  std::vector<bool> died = unmatched(forward), born = unmatched(backward);
  std::map<LineKind, PairMeasures> kinds;
  for (size_t r = 0; r < next.runs.size(); ++r) {
    const TrackedRun& run = next.runs[r];
    PairMeasures& m = kinds[run.kind];
    ++m.runs_next, m.length_next_px += run.length_px;
    if (born[r]) ++m.born, m.born_px += run.length_px;
  }
  for (size_t r = 0; r < prev.runs.size(); ++r) {
    const TrackedRun& run = prev.runs[r];
    PairMeasures& m = kinds[run.kind];
    ++m.runs_prev, m.length_prev_px += run.length_px, m.samples += run.samples.size();
    if (died[r]) ++m.died, m.died_px += run.length_px;
    for (size_t j = 0; j + 1 < run.samples.size(); ++j) {
      const TrackedSample &a = run.samples[j], &b = run.samples[j + 1];
      if (b.arc_px > a.arc_px) m.stretch.push_back(std::abs(std::abs(b.s - a.s) / (b.arc_px - a.arc_px) - 1));
    }
    for (size_t j = 0; j < run.samples.size(); ++j) {
      if (!forward[r][j]) continue;
      const Landing& l = *forward[r][j];
      const TrackedSample& q = run.samples[j];
      ++m.matched;
      m.slide_px.push_back(slide(run, q, next.runs[l.run], l));
      m.alpha_change.push_back(std::abs(l.alpha - q.alpha));
      m.width_change_px.push_back(std::abs(l.width - q.width));
      m.offset_change_px.push_back(glm::distance(l.offset, q.offset));
    }
  }
  std::vector<std::pair<std::string, PairMeasures>> out;
  PairMeasures all;
  for (const auto& [kind, m] : kinds) {
    out.emplace_back(line_kind_name(kind), m);
    accumulate(all, m);
  }
  out.emplace_back("all", std::move(all));
  return out;
}

Stats stats(std::vector<double> v) {
  double nan = std::numeric_limits<double>::quiet_NaN();
  if (v.empty()) return {nan, nan, nan, nan};
  std::sort(v.begin(), v.end());
  auto quantile = [&](double q) {
    double at = q * double(v.size() - 1);
    size_t i = size_t(at);
    return i + 1 < v.size() ? std::lerp(v[i], v[i + 1], at - double(i)) : v[i];
  };
  return {std::accumulate(v.begin(), v.end(), 0.0) / double(v.size()), quantile(0.5), quantile(0.95), v.back()};
}

}  // namespace plumbago::temporal_coherence
