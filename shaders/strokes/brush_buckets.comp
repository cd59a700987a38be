#version 450 core
// Coherent silhouettes' votes bucketed by run on the GPU, for the fit
// (shaders/strokes/brush_fit.comp): STEP_COUNT counts each run's votes (one invocation a
// brush sample, shaders/strokes/brush_votes.comp's slots); after a prefix sum, STEP_SCATTER
// puts each vote in its run's bucket (in any order: the fit sorts a run's votes) and
// STEP_BOUNDS gives each run the knots its fit may write (gpu/strokes/brush_fit.hpp
// knot_bound; none without votes); after a prefix sum of those, STEP_RUNS writes each run's
// record: its length s1 - s0, its votes and its first knot, and the fit's run count.
layout(local_size_x = 64) in;

struct Vote {  // shaders/strokes/brush_votes.comp Vote; run kNoVote: none
  double s, t;
  uint run, stroke, path, pad;
};
struct FitVote {  // shaders/strokes/brush_fit.comp Vote
  double s, t;
  uint stroke, group, path, pad;
};
struct FitRun {  // shaders/strokes/brush_fit.comp Run
  double length;
  uint first_vote, vote_count, first_knot, knot_count, path, pad;
};
struct Run {  // strokes/window_paths.glsl Run
  uint path, flags;
  double s0, s1;
};
struct Params {  // shaders/strokes/brush_fit.comp Params
  double sample_px, jump_px, knot_px, scale_weight, distort_weight;
  uint claim_votes, run_count;
};

layout(std430, binding = 0) readonly buffer Votes { Vote votes[]; };
layout(std430, binding = 1) buffer Counts { uint counts[]; };  // per run listed: its votes, then (scanned) its first
layout(std430, binding = 2) buffer Fill { uint fill[]; };      // per run: votes put so far; then its knot bound
layout(std430, binding = 3) writeonly buffer FitVotes { FitVote fit_votes[]; };
layout(std430, binding = 4) writeonly buffer FitRuns { FitRun fit_runs[]; };
layout(std430, binding = 5) readonly buffer RunRows { Run run_rows[]; };
layout(std430, binding = 6) readonly buffer Listed { uint listed[]; };  // the runs listed, at listed_at
layout(std430, binding = 7) buffer FitParams { Params p; };

uniform uint vote_slots, listed_at;

const uint kNoVote = 0xffffffffu;

#if defined(STEP_COUNT) || defined(STEP_SCATTER)
void main() {
  for (uint i = gl_GlobalInvocationID.x; i < vote_slots; i += gl_NumWorkGroups.x * 64u) {
    Vote v = votes[i];
    if (v.run == kNoVote) continue;
#ifdef STEP_COUNT
    atomicAdd(counts[v.run], 1u);
#else
    fit_votes[counts[v.run] + atomicAdd(fill[v.run], 1u)] = FitVote(v.s, v.t, v.stroke, 0u, v.path, 0u);
#endif
  }
}
#else
void at_run(uint r) {
  Run run = run_rows[r];
  uint votes_of = counts[r + 1u] - counts[r];
#ifdef STEP_BOUNDS
  fill[r] = votes_of == 0u ? 0u : uint(floor((run.s1 - run.s0) / p.knot_px)) + 4u * votes_of + 2u;
#else
  fit_runs[r] = FitRun(run.s1 - run.s0, counts[r], votes_of, fill[r], 0u, 0xffffffffu, 0u);
  if (r == 0u) p.run_count = listed[listed_at];
#endif
}

void main() {
  for (uint r = gl_GlobalInvocationID.x; r < listed[listed_at]; r += gl_NumWorkGroups.x * 64u) at_run(r);
}
#endif
