#version 450 core
// Each visible run's brush parameter (Kalnins et al. 2003) from the GPU's fit
// (shaders/strokes/brush_fit.comp) into the stroke samples' inputs (strokes/stroke_runs.glsl
// RunIn.knot_count: knots after the run's points), around run_inputs.comp's steps:
// STEP_COUNT, after its count, adds each run's knots to its points; STEP_COPY, after its
// write, copies them after the run's polyline. A run of fewer than 2 knots keeps t = s.
layout(local_size_x = 64) in;

#include "strokes/fit_run.glsl"
#include "strokes/stroke_runs.glsl"

layout(std430, binding = 0) readonly buffer FitRuns { FitRun fit_runs[]; };
layout(std430, binding = 1) readonly buffer Knots { dvec2 knots[]; };
layout(std430, binding = 2) buffer PointCounts { uint point_counts[]; };  // run_inputs.comp's
layout(std430, binding = 3) buffer RunsIn { RunIn runs_in[]; };
layout(std430, binding = 4) buffer Points { dvec2 points[]; };
layout(std430, binding = 5) readonly buffer RunArgs { uint run_args[4]; };  // over the runs listed

uint knots_of(uint run) {
  uint n = fit_runs[run].knot_count;
  return n >= 2u ? n : 0u;
}

void at_run(uint run) {
#ifdef STEP_COUNT
  point_counts[run] += knots_of(run);
#else
  RunIn r = runs_in[run];
  if (r.point_count == 0u) return;  // not drawn: past the buffers
  uint n = knots_of(run), from = fit_runs[run].first_knot;
  for (uint k = 0u; k < n; ++k) points[r.first_point + r.point_count + k] = knots[from + k];
  runs_in[run].knot_count = n;
#endif
}

void main() {
  for (uint run = gl_GlobalInvocationID.x; run < run_args[3]; run += gl_NumWorkGroups.x * 64u) at_run(run);
}
