// The per-frame measures of the temporal-coherence study (docs/conventions.md, "Temporal coherence";
// experiments/temporal_coherence/README.md) over the tracked strokes of two consecutive
// frames, per line kind: texture sliding along strokes, strokes born and dying, and the
// change of alpha and width at the same point of a stroke. Kinds are whatever the frames'
// runs hold (LineKind, named by line_kind_name), so a new kind gets its own rows.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "experiments/temporal_coherence/stroke_track.hpp"

namespace plumbago::temporal_coherence {

struct PairMeasures {
  size_t runs_prev = 0, runs_next = 0;            // strokes drawn in each frame
  double length_prev_px = 0, length_next_px = 0;  // and their total length
  size_t died = 0;                  // strokes of prev none of whose samples lands on next (carry prev -> next)
  size_t born = 0;                  // strokes of next none of whose samples lands on prev (carry next -> prev)
  double died_px = 0, born_px = 0;  // their total length
  size_t samples = 0, matched = 0;  // samples of prev, and those that land on next
  // Per sample of prev that lands on next: how far its texture coordinate moved along the
  // stroke (slide()), and |alpha_next - alpha_prev|, |width_next - width_prev| (px) and
  // |offset_next - offset_prev| (px, window vectors: the displacement of Kalnins et al. 2002, §4.3) there.
  std::vector<double> slide_px, alpha_change, width_change_px, offset_change_px;
  // Per piece between consecutive samples of a stroke of prev: how far the texture is
  // stretched or squeezed in the image, ||Δs| / Δarc - 1| (0 under arc length: the
  // uniformity that Kalnins et al. 2003 trade against coherence).
  std::vector<double> stretch;
};

// How far the texture slid along the stroke at the point where `sample` of `from` lands on
// `to`: |s_to - s_from| in px (u x texture_period_px); when both strokes are loops, around
// the loop the shorter way (a loop's texture starts at its seam, anywhere).
double slide(const TrackedRun& from, const TrackedSample& sample, const TrackedRun& to, const Landing& landing);

// Adds m's counts and lists to `into` (measures pooled over kinds, or over frame pairs).
void accumulate(PairMeasures& into, const PairMeasures& m);

// Per line kind of either frame, in LineKind order, then "all" over every kind.
std::vector<std::pair<std::string, PairMeasures>> pair_measures(const FrameStrokes& prev, const FrameStrokes& next,
                                                                const MatchParams& params = {});

// Summary of a list; every field NaN when it is empty. p95 and median interpolate linearly
// between order statistics (numpy's default).
struct Stats {
  double mean, median, p95, max;
};
Stats stats(std::vector<double> values);

}  // namespace plumbago::temporal_coherence
