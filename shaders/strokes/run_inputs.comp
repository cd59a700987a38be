#version 450 core
// Stroke samples on the GPU, step 0 (Kalnins et al. 2002, §4.1, §4.3, §5.3): each visible run's
// window polyline and style, one invocation per run, from the paths and runs the visibility
// steps left on the GPU (gpu/strokes/window_paths.hpp) and the scene's styles, examples and
// Markov chains, put up once (gpu/strokes/run_styles.hpp). What it computes is
// common/strokes/visibility.cpp run_along and common/strokes/stroke.cpp RunStyles::of.
//   STEP_ARGS:  one invocation: the dispatch over the runs listed, and their count;
//   STEP_COUNT: per run, its polyline's points and the offsets it makes (a synthesized
//               example's, a decal's pressure), into two tables prefix-summed after it;
//   STEP_WRITE: per run, its points, its offsets after the examples' own, and its RunIn.
// The rows past the runs listed are neither visited nor read: the prefix sums go over the
// runs listed (gpu/gl/scan.hpp).
layout(local_size_x = 64) in;

#include "strokes/stroke_runs.glsl"
#include "strokes/fit_run.glsl"
#define PATHS_BINDING 0
#define POINTS_BINDING 1
#include "strokes/window_paths.glsl"
#include "strokes/run_walk.glsl"
#include "util/lerp.glsl"
#include "util/random.glsl"

struct Style {  // gpu/strokes/run_styles.hpp StyleRow
  vec4 color_layer;
  float width, alpha, taper, fade, halo, flare, sample_px, period;
  uint flags;    // kPressureWidth | kPressureAlpha
  uint offsets;  // kNone, kOwn, kDrawn, kSynthesized, kDecal (common/strokes/stroke.hpp RunOffsets)
  uint first_example, example_count;  // kOwn: the style's; kDrawn: the kind's
  uint first_state, state_count;      // kSynthesized: the chain's states,
  uint first_start, start_count;      // each example's first one (in targets[].to),
  uint markov, pad;                   // and whether it walks by its rows (else by successors)
  double step;                        // px between synthesized offsets
};
struct Example {  // ExampleRow
  double length;
  uint first_offset, offset_count, repeats, pad;
};
struct State {  // StateRow: a chain state, its row of targets
  double value, pressure;
  uint first_target, target_count, successor, pad;
};
struct Target {  // TargetRow: a row's allowed target and its cumulative weight; or a start
  double cumulative;
  uint to, pad;
};
const uint kNone = 0u, kOwn = 1u, kDrawn = 2u, kSynthesized = 3u, kDecal = 4u;

layout(std430, binding = 2) readonly buffer RunRows { Run run_rows[]; };
layout(std430, binding = 3) readonly buffer Styles { Style styles[]; };
layout(std430, binding = 4) readonly buffer Examples { Example examples[]; };
layout(std430, binding = 5) readonly buffer States { State states[]; };
layout(std430, binding = 6) readonly buffer Targets { Target targets[]; };
// Per run listed, then (scanned) its first: points and offsets; the totals after them.
layout(std430, binding = 7) buffer PointCounts { uint point_counts[]; };
layout(std430, binding = 8) buffer OffsetCounts { uint offset_counts[]; };
layout(std430, binding = 9) writeonly buffer RunsIn { RunIn runs_in[]; };
layout(std430, binding = 10) writeonly buffer Points { dvec2 points[]; };
layout(std430, binding = 11) writeonly buffer Offsets { Offset offsets[]; };  // after the examples' own
layout(std430, binding = 12) readonly buffer Listed { uint listed[]; };        // the runs listed, at listed_at
layout(std430, binding = 13) buffer RunArgs { uint run_args[4]; };  // (groups, 1, 1) over the runs, their count
layout(std430, binding = 14) readonly buffer FitRuns { FitRun fit_runs[]; };  // with_fit: per run, its brush path

uniform uint run_count, seed;  // run_count: the rows' bound
uniform uint listed_at;
uniform uint own_offsets;  // the examples' offsets, at the start of offsets[]
// The points and offsets the buffers hold: a run whose own would pass them is not drawn (a
// frame sized by an earlier one, gpu/core/pipeline.hpp Renderer::render_frame).
uniform uint point_capacity, offset_capacity;
// Coherent silhouettes (Kalnins et al. 2003): whether they are on, whether this frame has the
// fit's brush paths (else each run starts a new one), and their offsets' period (px, a
// whole number: a float holds it exactly, and not every GL exports double uniforms' setters).
uniform uint coherent_silhouettes, with_fit;
uniform float brush_period_px;
double brush_period() { return double(brush_period_px); }

#include "strokes/brush_path.glsl"

// A path's pieces: 0. the run's window polyline (run_along).
uint polyline_point(uint at, uint n, dvec2 p) {
#if defined(STEP_WRITE)
  points[at + n] = p;
#endif
  return n + 1u;
}

uint run_polyline(Run r, Path p, uint at) {
  uint n = 0u;
  RunWalk w = start_run_walk(r, p);
  for (RunPoint q; next_run_point(w, q);) n = polyline_point(at, n, q.window);
  return n;
}

uint put_offset(uint at, uint n, double t, double displacement, double pressure) {
#if defined(STEP_WRITE)
  offsets[at + n] = Offset(t, displacement, pressure, 0u, 0u);
#endif
  return n + 1u;
}

// A decal's or hatch's pressure example over the run (common/strokes/stroke.cpp decal_style):
// the path's drawn pressure at s0, at every path point between, and at s1.
double pressure_at(Path p, double s) {
  uint k = segment_at(p, wrapped(p, s)), next = min(k + 1u, p.points - 1u);
  double length = point(p, next).s - point(p, k).s;
  double t = length > 0.0lf ? clamp((s - point(p, k).s) / length, 0.0lf, 1.0lf) : 0.0lf;
  return point(p, k).pressure + t * (point(p, next).pressure - point(p, k).pressure);
}

uint pressure_offsets(Run r, Path p, uint at) {
  double length = max(r.s1 - r.s0, 1.0lf);
  uint n = put_offset(at, 0u, 0.0lf, 0.0lf, pressure_at(p, r.s0));
  for (uint k = 0u; k < p.points; ++k) {
    double s = point(p, k).s;
    if (s > r.s0 && s < r.s1) n = put_offset(at, n, (s - r.s0) / length, 0.0lf, point(p, k).pressure);
  }
  return put_offset(at, n, (r.s1 - r.s0) / length, 0.0lf, pressure_at(p, r.s1));
}

// common/strokes/offset_synthesis.cpp: a Markov walk from a random example's start, one
// uniform for it and one per transition of the rows (none for the successors' fallback).
struct Walk {
  uint key, drawn, state;
};
Walk start_walk(Style st, uint key) {
  Walk w = Walk(key, 0u, 0u);
  if (st.state_count == 0u) return w;
  uint e = min(uint(uniform_at(key, w.drawn++) * double(st.start_count)), st.start_count - 1u);
  w.state = targets[st.first_start + e].to;
  return w;
}
void step_walk(Style st, inout Walk w) {
  if (st.state_count == 0u) return;
  State here = states[st.first_state + w.state];
  if (st.markov == 0u) {
    w.state = here.successor;
    return;
  }
  double u = uniform_at(w.key, w.drawn++) * targets[here.first_target + here.target_count - 1u].cumulative;
  uint lo = 0u, hi = here.target_count;  // the first cumulative weight above u
  while (lo < hi) {
    uint mid = (lo + hi) / 2u;
    if (targets[here.first_target + mid].cumulative <= u) lo = mid + 1u; else hi = mid;
  }
  w.state = targets[here.first_target + min(lo, here.target_count - 1u)].to;
}
double value_of(Style st, Walk w) { return st.state_count == 0u ? 0.0lf : states[st.first_state + w.state].value; }
double pressure_of(Style st, Walk w) {
  return st.state_count == 0u ? 1.0lf : states[st.first_state + w.state].pressure;
}

// OffsetSynthesizer::synthesize_example over the run's length: an offset every step while
// below the length, then one at t = 1 between the two around it.
uint synthesized_offsets(Style st, Run r, Path p, uint ord, uint at) {
  double length = max(r.s1 - r.s0 > 0.0lf ? r.s1 - r.s0 : 0.0lf, 1.0lf), step = st.step;
  uint count = uint(ceil(length / step * (1.0lf - 1e-12lf))) + 1u;  // offset_count
  double end = length / step;
  uint k0 = min(uint(floor(end)), count - 1u), k1 = min(k0 + 1u, count - 1u);
  double f = k0 + 1u < count ? end - double(k0) : 0.0lf;
  Walk w = start_walk(st, stream_key(seed, p.key, ord, kOffsetWalk));
  double v0 = 0.0lf, p0 = 1.0lf, v1 = 0.0lf, p1 = 1.0lf;
  uint n = 0u;
  for (uint k = 0u; k < count; ++k) {
    if (k > 0u) step_walk(st, w);
    if (double(k) * step < length * (1.0lf - 1e-12lf))
      n = put_offset(at, n, double(k) * step / length, value_of(st, w), pressure_of(st, w));
    if (k == k0) v0 = value_of(st, w), p0 = pressure_of(st, w);
    if (k == k1) v1 = value_of(st, w), p1 = pressure_of(st, w);
  }
  return put_offset(at, n, 1.0lf, lerp(v0, v1, f), lerp(p0, p1, f));
}

// Whether the run draws its brush path's synthesized offsets along t (RunStyles::of): a
// silhouette's (SampleKind 1) where silhouettes are coherent.
bool on_brush_path(Style st, Path p) {
  return st.offsets == kSynthesized && coherent_silhouettes != 0u && (p.kind & 15u) == 1u;
}

// OffsetSynthesizer::synthesize_period: the run's brush path's walk, an offset every step
// while below the period, from the stream keyed by the brush path.
uint brush_path_offsets(Style st, Path p, uint run, uint at) {
  uint count = uint(ceil(brush_period() / st.step * (1.0lf - 1e-12lf)));
#if defined(STEP_WRITE)
  uint fitted = with_fit != 0u ? fit_runs[run].path : kNewBrushPath;
  Walk w = start_walk(st, brush_path_key(fitted, seed, p.key, run));
  for (uint k = 0u; k < count; ++k) {
    if (k > 0u) step_walk(st, w);
    put_offset(at, k, double(k) * st.step / brush_period(), value_of(st, w), pressure_of(st, w));
  }
#endif
  return count;
}

// The offsets the run makes itself (written from `at`): their count.
uint own_run_offsets(Style st, Run r, Path p, uint run, uint at) {
  if (st.offsets == kDecal) return pressure_offsets(r, p, at);
  if (on_brush_path(st, p)) return brush_path_offsets(st, p, run, at);
  if (st.offsets == kSynthesized) return synthesized_offsets(st, r, p, ordinal(run), at);
  return 0u;
}

// The example a kOwn or kDrawn run stamps (RunStyles::of: the drawn ones in turn along the
// path, from one its key picks).
Example stamped_example(Style st, Path p, uint run) {
  if (st.offsets == kOwn) return examples[st.first_example];
  double start = uniform_at(stream_key(seed, p.key, kStampStart), 0u);
  return examples[st.first_example + (uint(start * double(st.example_count)) + ordinal(run)) % st.example_count];
}

#if defined(STEP_WRITE)
RunIn run_input(Style st, Run r, Path p, uint run, uint points_at, uint point_count) {
  RunIn made;
  made.color_layer = st.color_layer;
  made.first_point = points_at, made.point_count = point_count;
  made.width = float(double(st.width) * p.width_scale), made.alpha = float(double(st.alpha) * p.alpha_scale);
  made.taper = st.taper, made.fade = st.fade, made.halo = st.halo, made.flare = st.flare;
  made.sample_px = st.sample_px, made.period = st.period;
  made.flags = (r.flags & (kClosed | kOccludedStart | kOccludedEnd)) | st.flags, made.knot_count = 0u;
  made.first_offset = 0u, made.offset_count = 0u, made.example_length = 0.0lf;
  if (st.offsets == kOwn || st.offsets == kDrawn) {
    Example e = stamped_example(st, p, run);
    made.first_offset = e.first_offset, made.offset_count = e.offset_count, made.example_length = e.length;
    if (e.repeats != 0u) made.flags |= kRepeats;
  } else if (st.offsets != kNone) {  // made for the run: does not repeat; or its brush path's
    made.first_offset = own_offsets + offset_counts[run];
    made.offset_count = offset_counts[run + 1u] - offset_counts[run];
    made.example_length = max(r.s1 - r.s0 > 0.0lf ? r.s1 - r.s0 : 0.0lf, 1.0lf);
    if (on_brush_path(st, p)) made.example_length = brush_period(), made.flags |= kRepeats | kUnscaled;
  }
  return made;
}
#endif

#if defined(STEP_ARGS)
void main() {
  uint n = min(listed[listed_at], run_count);
  run_args = uint[4](clamp((n + 63u) / 64u, 1u, 65535u), 1u, 1u, n);
}
#else
void at_run(uint run) {
  Run r = run_rows[run];
  Path p = paths[r.path];
  Style st = styles[p.style];
#if defined(STEP_COUNT)
  point_counts[run] = run_polyline(r, p, 0u);
  offset_counts[run] = own_run_offsets(st, r, p, run, 0u);
#else
  if (point_counts[run + 1u] > point_capacity || own_offsets + offset_counts[run + 1u] > offset_capacity) {
    runs_in[run] = run_input(st, r, p, run, 0u, 0u);  // past the buffers: not drawn
    return;
  }
  uint n = run_polyline(r, p, point_counts[run]);
  own_run_offsets(st, r, p, run, own_offsets + offset_counts[run]);
  runs_in[run] = run_input(st, r, p, run, point_counts[run], n);
#endif
}

// Each invocation every (groups x 64)th run listed.
void main() {
  for (uint run = gl_GlobalInvocationID.x; run < run_args[3]; run += gl_NumWorkGroups.x * 64u) at_run(run);
}
#endif
