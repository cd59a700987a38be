#version 450 core
// Coherent silhouettes' brush samples on the GPU (Kalnins et al. 2003): step 1. of
// common/strokes/coherent_silhouettes.hpp, in double, one invocation per visible run as the
// visibility steps leave them on the GPU: a silhouette run of length L = s1 - s0 is sampled
// at s = L j / n, n = max(1, ceil(L / sample_px)) (a whole closed path's last sample is its
// first: left out), each sample the world point drawn there, its brush parameter t(s) (the
// run's knots; none: t = s) and the run's brush path (strokes/brush_path.glsl). The world
// point is the window point at s0 + s unprojected at its depth (window_paths.glsl depth_at):
// the point of the world segment that projects there, which the reference's world_at
// interpolates. STEP_COUNT counts each run's
// samples; after a prefix sum over the counts, STEP_WRITE writes them and how many it wrote
// (what the next frame's votes read: shaders/strokes/brush_votes.comp).
layout(local_size_x = 64) in;

#define PATHS_BINDING 0
#define POINTS_BINDING 1
#include "strokes/window_paths.glsl"
#include "strokes/fit_run.glsl"

struct Sample {  // gpu/strokes/brush_samples.cpp SampleRecord (shaders/strokes/brush_votes.comp Sample)
  double x, y, z, t;
  uint stroke, path;
};
struct Frame {  // world to clip and back, world to view, view to clip; the window; the spacing
  dmat4 clip, unclip, view, projection;
  double width, height, sample_px, pad;
};

layout(std430, binding = 2) readonly buffer RunRows { Run run_rows[]; };
layout(std430, binding = 3) readonly buffer Listed { uint listed[]; };  // the runs listed, at listed_at
layout(std430, binding = 4) buffer Counts { uint counts[]; };          // per run listed, then (scanned) its first
layout(std430, binding = 5) readonly buffer FitRuns { FitRun fit_runs[]; };  // per run: its knots
layout(std430, binding = 6) readonly buffer Knots { dvec2 knots[]; };
layout(std430, binding = 7) writeonly buffer Samples { Sample samples[]; };
layout(std430, binding = 8) readonly buffer FrameBlock { Frame f; };
layout(std430, binding = 9) writeonly buffer Total { uint total; };  // the samples written

uniform uint listed_at, capacity, with_knots, seed;

#include "util/random.glsl"
#include "strokes/brush_path.glsl"

dvec2 brush_knot(uint i) { return knots[i]; }
#include "strokes/brush_parameter.glsl"

const uint kSilhouette = 1u, kWholeRun = 1u;  // SampleKind; Run.flags

uint sample_intervals(Run r) { return uint(max(1.0lf, ceil((r.s1 - r.s0) / f.sample_px))); }

uint sample_count(Run r) {
  if ((paths[r.path].kind & 15u) != kSilhouette) return 0u;
  return sample_intervals(r) + ((r.flags & kWholeRun) != 0u ? 0u : 1u);
}

// The world point seen at window position w and linear view depth d.
dvec3 unproject(dvec2 w, double d) {
  dvec2 ndc = w / dvec2(f.width, f.height) * 2.0lf - 1.0lf;
  double z_view = -d;
  double z_clip = f.projection[2][2] * z_view + f.projection[3][2];
  double w_clip = f.projection[2][3] * z_view + f.projection[3][3];
  dvec4 world = f.unclip * dvec4(ndc * w_clip, z_clip, w_clip);
  return world.xyz / world.w;
}

#ifdef STEP_COUNT
void at_run(uint r) { counts[r] = sample_count(run_rows[r]); }
#endif

#ifdef STEP_WRITE
void at_run(uint r) {
  Run run = run_rows[r];
  Path p = paths[run.path];
  uint count = sample_count(run), n = sample_intervals(run), at = counts[r];
  FitRun k = with_knots != 0u ? fit_runs[r] : FitRun(0.0lf, 0u, 0u, 0u, 0u, kNewBrushPath, 0u);
  uint path = brush_path_key(k.path, seed, p.key, r);
  double length = run.s1 - run.s0;
  for (uint j = 0u; j < count && at + j < capacity; ++j) {
    double s = length * double(j) / double(n);
    dvec3 world = unproject(window_at(p, run.s0 + s), depth_at(p, run.s0 + s));
    samples[at + j] = Sample(world.x, world.y, world.z, brush_t_at(k.first_knot, k.knot_count, s), r, path);
  }
}
#endif

void main() {
#ifdef STEP_WRITE
  if (gl_GlobalInvocationID.x == 0u) total = min(counts[listed[listed_at]], capacity);
#endif
  for (uint r = gl_GlobalInvocationID.x; r < listed[listed_at]; r += gl_NumWorkGroups.x * 64u) at_run(r);
}
