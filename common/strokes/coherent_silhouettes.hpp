// Coherent stylized silhouettes (Kalnins, Davidson, Markosian and Finkelstein 2003): each
// silhouette stroke's brush parameter t (px: u = t / texture_period_px) is carried over the
// surface from frame to frame, where the 2002 paper restarts it at each visible run's start
// (common/strokes/base_stroke.hpp 6.), so that a stroke's texture stays where it was drawn.
//
// 1. Brush samples. The silhouette strokes of a frame are sampled every `sample_px` of
//    window arc length along each visible run: the surface point drawn there and its t.
// 2. Votes. In the next frame each brush sample is projected; the nearest point of a visible
//    silhouette run within `search_px` whose linear view depth agrees within
//    `depth_tolerance` (relative) takes its vote (s from the run's start, t, the stroke it came
//    from). The paper walks the new ID image along the projected normal for the nearest
//    silhouette pixel; the visible runs are what that image's test leaves visible.
// 3. Groups. A run's votes in order of s join the group of the stroke they came from while
//    they follow its last vote within 3 sample_px of s and their t changes by |Δs| within
//    `jump_px`; else they start a new group (the paper's brush paths split at gaps and at
//    jumps of t). Largest first, each group claims what of its span (first to last vote) no
//    larger group claimed, where `claim_votes` of its votes lie (one vote fixes t's phase;
//    with fewer than 2 the rate is σ = +1, 4.); gaps between claims go half to either
//    side, the run's ends to the nearest claim. Each section follows its group, and t jumps
//    between sections (one run, several brush paths). A run with no claim has none: t = s,
//    the 2002 paper's arc length from the run's start.
// 4. Fit (the paper's optimization of coherence against uniformity), per section of length
//    L: t is piecewise linear on n = max(1, round(L / knot_px)) equal intervals of length h,
//    knots t_k, fitted to the section's votes:
//      E = sum_i (t(s_i) - t_i)^2                              coherence: the votes
//        + scale_weight   sum_k (t_{k+1} - t_k - σ h)^2        uniformity: rate σ = ±1 in the image
//        + distort_weight sum_k (t_{k-1} - 2 t_k + t_{k+1})^2  smooth stretching
//    σ the sign of the votes' slope (a path may be traced the other way round this frame;
//    +1 for a single vote).
//    The normal equations are solved by Eigen's LDLT. Beyond its votes the fit runs on at
//    rate σ: the section is covered whole.
// 5. Brush paths. Each brush sample also carries the brush path its stroke drew: a key that
//    a run keeps from frame to frame, so that what is drawn along a path's t stays with it.
//    A run draws the brush path of its largest section (the most votes; equal: the first in
//    s); a run with no section starts a new one, keyed as the 2002 synthesis keys a run's
//    walk (the scene seed, its path's key, its ordinal: common/strokes/stroke.hpp
//    brush_path_key). A style whose offsets are synthesized (Kalnins et al. 2002, §5.3) draws
//    on a coherent silhouette its brush path's walk, one offset every step along t, made
//    periodic over kBrushOffsetPeriodPx (the walk's last offset runs into its first) and
//    stamped at t (common/strokes/base_stroke.hpp 4.) at full size: the offsets stay on the
//    surface as the texture does. On t in [0, L] a new run draws what the 2002 synthesis
//    draws along its arc length (where L <= kBrushOffsetPeriodPx - 4). Reading: one brush path a
//    run; where two merge, the smaller one's offsets change once.
//
// The parameters are the scene's `coherence.*` (plumbago params). Their defaults are those of
// jot, the authors' system (votes searched within 6 px, knots every 48 px, unit weights), but
// for two measured in experiments/temporal_coherence: brush samples every 2 px, not jot's
// 8 (the slide's p95 5.3x under arc length on the statue, not 3.5x: the 5x met on
// every orbit, for a stage still under 20% of the GPU's stroke frame), and a claim needs 2
// votes (1: lower slide p95 on the statue, higher on the torus and cup).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "common/scene/camera.hpp"
#include "common/strokes/base_stroke.hpp"
#include "common/strokes/visibility.hpp"

namespace plumbago {

struct CoherenceParams {
  static constexpr const char* stage = "coherence";
  double sample_px, search_px, depth_tolerance, jump_px, knot_px, scale_weight, distort_weight;
  int claim_votes;
  template <class V>
  void visit(V& v) {
    v.real(
        sample_px, "sample_px", 2.0, 1.0, 64.0,
        "coherent silhouettes' brush samples along each visible silhouette run, window px apart (Kalnins et al. 2003; "
        "jot's 8 px slides more, experiments/temporal_coherence)");
    v.real(search_px, "search_px", 6.0, 0.5, 64.0,
           "a brush sample of the last frame votes for the nearest visible silhouette point within this (px)");
    v.real(depth_tolerance, "depth_tolerance", 0.01, 0.0, 1.0,
           "and only where their linear view depths agree within this share of its own");
    v.real(jump_px, "jump_px", 4.0, 0.0, 1000.0,
           "a run's votes from one stroke split where |delta t| departs from delta s by more (px)");
    v.integer(claim_votes, "claim_votes", 2, 1, 64,
              "a group of votes parameterizes a section of its run where it has this many votes there");
    v.real(knot_px, "knot_px", 48.0, 4.0, 4096.0, "the knots of the fit of t this far apart along a section (px)");
    v.real(scale_weight, "scale_weight", 1.0, 0.0, 1e6,
           "the fit's weight on uniformity: t at rate 1 in the image (against coherence, the votes' weight 1)");
    v.real(distort_weight, "distort_weight", 1.0, 0.0, 1e6,
           "the fit's weight on the second differences of t at its knots: smooth stretching");
  }
};

// 5. The period of a brush path's synthesized offsets along t (px).
inline constexpr double kBrushOffsetPeriodPx = 1024;
// A run's brush path before it is known: a run with no section starts a new one.
inline constexpr uint32_t kNewBrushPath = 0xffffffffu;

// A visible run's brush: its parameter (knots; none: t = s) and its brush path (5.).
struct RunBrush {
  BrushParameter knots;
  uint32_t path = kNewBrushPath;
};

// 1. A surface point a silhouette stroke drew, with its t, the stroke's index among its
// frame's runs and its brush path (5.).
struct BrushSample {
  glm::dvec3 world;
  double t;
  uint32_t stroke, path;
};

// Every `sample_px` along each visible silhouette run (runs[i] drawn with brushes[i]; a run
// past the end of `brushes` by t = s and a new brush path); `seed` the scene's, which keys
// new brush paths.
std::vector<BrushSample> brush_samples(const WindowLines& lines, const Visibility& visibility,
                                       const std::vector<RunBrush>& brushes, const CoherenceParams& p, uint32_t seed);

// 2. A vote for run `run` of the new frame: at its s, t, from the previous frame's `stroke`,
// which drew brush path `path`.
struct BrushVote {
  uint32_t run;
  double s, t;
  uint32_t stroke, path;
};

std::vector<BrushVote> brush_votes(const std::vector<BrushSample>& previous, const Camera& camera,
                                   const WindowLines& lines, const Visibility& visibility, const CoherenceParams& p);

// 3.-5. One run's brush from its votes (any order), L its window length: its sections' fits
// and the brush path of its largest; none (t = s, a new path) where no group claims a section.
RunBrush fit_brush_parameter(std::vector<BrushVote> votes, double length_px, const CoherenceParams& p);

// Each visible run's brush in the new frame (none where no group votes for it).
std::vector<RunBrush> coherent_parameters(const std::vector<BrushSample>& previous, const Camera& camera,
                                          const WindowLines& lines, const Visibility& visibility,
                                          const CoherenceParams& p);

}  // namespace plumbago
