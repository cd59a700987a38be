#version 450 core
// Coherent silhouettes' votes on the GPU (Kalnins et al. 2003): step 2. of
// common/strokes/coherent_silhouettes.hpp, in double as the reference makes them, one
// invocation per brush sample of the last frame (the first `total` of `slots`; a slot past
// them has no vote): its world point projected with this frame's camera votes for the
// nearest point, within search_px, of a visible silhouette run of this frame (the runs'
// window polylines as strokes/run_walk.glsl walks them, the pieces' depths linear between
// their ends) whose depth agrees within depth_tolerance of its own; the nearest, among
// equals the first in run and piece order, as the reference takes it. STEP_BOXES first
// boxes each run's window polyline, so that STEP_VOTE walks only the runs whose box, grown
// by search_px, holds the sample.
layout(local_size_x = 64) in;

#define PATHS_BINDING 0
#define POINTS_BINDING 1
#include "strokes/window_paths.glsl"
#include "strokes/run_walk.glsl"
#include "util/lerp.glsl"

struct Sample {  // gpu/strokes/brush_votes.cpp SampleRecord
  double x, y, z, t;
  uint stroke, pad;
};
struct Vote {  // gpu/strokes/brush_votes.cpp VoteRecord; run kNoVote: none
  double s, t;
  uint run, stroke;
};
struct Frame {  // world to clip, to view; the window; the search
  dmat4 clip, view;
  double width, height, search_px, depth_tolerance;
};

layout(std430, binding = 2) readonly buffer RunRows { Run run_rows[]; };
layout(std430, binding = 3) readonly buffer Listed { uint listed[]; };  // the runs listed, at listed_at
layout(std430, binding = 4) readonly buffer Samples { Sample samples[]; };
layout(std430, binding = 5) writeonly buffer Votes { Vote votes[]; };
layout(std430, binding = 6) readonly buffer FrameBlock { Frame f; };
layout(std430, binding = 7) readonly buffer Total { uint total; };  // the samples (brush_samples.comp)
layout(std430, binding = 8) buffer Boxes { dvec4 boxes[]; };  // per run listed: (x0, y0, x1, y1); x0 > x1: none

uniform uint slots, listed_at;

const uint kNoVote = 0xffffffffu, kSilhouette = 1u;  // SampleKind

// The window position and linear depth of a world point (common/strokes/strokes.hpp
// WindowProjection).
dvec3 project(dvec3 world) {
  dvec4 c = f.clip * dvec4(world, 1.0lf);
  double d = -(f.view * dvec4(world, 1.0lf)).z;
  return dvec3((c.x / c.w * 0.5lf + 0.5lf) * f.width, (c.y / c.w * 0.5lf + 0.5lf) * f.height, d);
}

// common/util/segment_grid.hpp nearest_on: the share along a -> b of its point nearest q.
double nearest_share(dvec2 a, dvec2 b, dvec2 q) {
  dvec2 d = b - a;
  double len2 = dot(d, d);
  return len2 > 0.0lf ? clamp(dot(q - a, d) / len2, 0.0lf, 1.0lf) : 0.0lf;
}

// The vote of a point seen at q (window, depth) among run r's pieces, if nearer than `best`.
void vote_on_run(uint r, dvec3 q, inout double best, inout Vote vote) {
  Run run = run_rows[r];
  Path p = paths[run.path];
  if ((p.kind & 15u) != kSilhouette) return;
  RunWalk w = start_run_walk(run, p);
  RunPoint a, b;
  if (!next_run_point(w, a)) return;
  for (double s = 0.0lf; next_run_point(w, b); a = b) {
    double next_s = s + distance(a.window, b.window);
    double t = nearest_share(a.window, b.window, q.xy);
    double d = distance(a.window + t * (b.window - a.window), q.xy);
    double depth = lerp(a.depth, b.depth, t);
    bool nearer = d < best || (d == best && vote.run == kNoVote);  // among equals, the first
    if (nearer && abs(depth - q.z) <= f.depth_tolerance * q.z) best = d, vote.run = r, vote.s = lerp(s, next_s, t);
    s = next_s;
  }
}

#ifdef STEP_BOXES
// Run r's box: a silhouette run's points (none: empty).
dvec4 run_box(uint r) {
  dvec4 box = dvec4(1.0lf, 0.0lf, 0.0lf, 0.0lf);
  Run run = run_rows[r];
  Path p = paths[run.path];
  if ((p.kind & 15u) != kSilhouette) return box;
  RunWalk w = start_run_walk(run, p);
  RunPoint a;
  if (next_run_point(w, a)) box = dvec4(a.window, a.window);
  while (next_run_point(w, a)) box = dvec4(min(box.xy, a.window), max(box.zw, a.window));
  return box;
}

void main() {
  for (uint r = gl_GlobalInvocationID.x; r < listed[listed_at]; r += gl_NumWorkGroups.x * 64u) boxes[r] = run_box(r);
}
#endif

#ifdef STEP_VOTE
// Whether a run of box b may hold a piece within search_px of q (a margin of 1e-6 px keeps
// the box's rounding from losing a piece at exactly search_px).
bool box_near(dvec4 b, dvec2 q) {
  double grow = f.search_px + 1e-6lf;
  return b.x <= b.z && all(greaterThanEqual(q, b.xy - grow)) && all(lessThanEqual(q, b.zw + grow));
}

void main() {
  for (uint i = gl_GlobalInvocationID.x; i < slots; i += gl_NumWorkGroups.x * 64u) {
    if (i >= total) {
      votes[i] = Vote(0.0lf, 0.0lf, kNoVote, 0u);
      continue;
    }
    Sample x = samples[i];
    dvec3 q = project(dvec3(x.x, x.y, x.z));
    Vote vote = Vote(0.0lf, x.t, kNoVote, x.stroke);
    double best = f.search_px;
    if (q.z > 0.0lf)
      for (uint r = 0u; r < listed[listed_at]; ++r)
        if (box_near(boxes[r], q.xy)) vote_on_run(r, q, best, vote);
    votes[i] = vote;
  }
}
#endif
