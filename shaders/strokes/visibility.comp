#version 450 core
// Visibility of stroke samples (Kalnins et al. 2002, §4.6, §4.1): the steps of gpu/strokes/visibility.cpp, one
// program each, doing what common/strokes/visibility.cpp defines. A path is split into entries:
// its segments, then one for its end. Prefix sums (gpu/gl/scan.hpp) run between the steps.
//   STEP_COUNT:   per entry, how many first-round samples a segment takes;
//   STEP_ENDS:    per path, its end entry's: an open path's end, and s = 0 where no segment took one;
//   STEP_SAMPLES: per entry, its samples at their prefix sum, each tested against the ID image;
//   STEP_CHANGES: per sample, whether the next one along its path disagrees: the change bisected to 1 px;
//   STEP_MARKS:   per sample, its change listed, and where a visible run starts (at most 2 a sample);
//   STEP_ARGS:    one invocation: the dispatches over the samples, whose count stays on the GPU;
//   STEP_RUNS:    per run start, the run to the next change;
//   STEP_TEST:    per sample of a given batch, the test alone (gpu::SampleTest).
layout(local_size_x = 64) in;  // kRowsGroup; STEP_TEST: gpu/gl/program.hpp dispatch_in_chunks

struct Sample {  // common/strokes/visibility.hpp VisibilitySample
  vec2 window;
  uint kind;  // 0 crease or border, 1 silhouette, 2 decal, 3 hatch (SampleKind)
  uint key;
  uint faces[2];
  uint byte_value;
  uint byte_window;  // at most 255; bit 8: a closed path (bytes compared around the seam)
};

uniform usampler2D ids;         // (key >> 16, key & 0xffff)
uniform usampler2D crease_ids;  // the same before the silhouettes' quads
uniform bool crease_under_silhouettes;  // strokes.crease_under_silhouettes

bool holds(uint value, Sample s) {
  if (value == 0u) return false;
  if (s.kind == 2u) return value == s.faces[0];
  if (s.kind == 3u) return value == s.faces[0] || value == s.faces[1];
  if (s.kind == 0u) return value == s.key || value == s.faces[0] || value == s.faces[1];
  if ((value >> 8) != s.key) return false;
  int d = abs(int(value & 0xffu) - int(s.byte_value));
  if ((s.byte_window & 0x100u) != 0u) d = min(d, 256 - d);
  return d <= int(s.byte_window & 0xffu);
}

// The test of common/strokes/visibility.cpp sample_visible: some pixel of the 3x3 box (5x5 for a hatch).
bool sample_visible(Sample s) {
  ivec2 size = textureSize(ids, 0);
  bool near_window =
      s.window.x > -2.0 && s.window.y > -2.0 && s.window.x < float(size.x + 2) && s.window.y < float(size.y + 2);
  if (!near_window) return false;
  ivec2 p = ivec2(floor(s.window));
  int r = s.kind == 3u ? 2 : 1;
  bool visible = false;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      ivec2 q = p + ivec2(dx, dy);
      if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size))) {
        uvec2 halves = texelFetch(ids, q, 0).xy;
        visible = visible || holds(halves.x << 16 | halves.y, s);
      }
    }
  if (visible || !crease_under_silhouettes || s.kind != 0u || any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size)))
    return visible;
  uvec2 under = texelFetch(crease_ids, p, 0).xy;  // its own pixel before the silhouettes' quads
  return holds(under.x << 16 | under.y, s);
}

#if defined(STEP_TEST)
layout(std430, binding = 0) readonly buffer Samples { Sample samples[]; };
layout(std430, binding = 1) writeonly buffer Flags { uint flags[]; };
uniform uint sample_count;
uniform uint first;  // of this dispatch (a batch may take several: 65535 groups at most each)

void main() {
  uint k = first + gl_GlobalInvocationID.x;
  if (k < sample_count) flags[k] = sample_visible(samples[k]) ? 1u : 0u;
}
#else

struct Tested {
  double s;
  double change;  // where that change is located
  uint flags;     // 1: visible; 2: the next sample along the path disagrees; 4: ... and is visible
  uint path;
};
#define PATHS_BINDING 0
#define POINTS_BINDING 1
#include "strokes/window_paths.glsl"
#include "util/rows.glsl"
layout(std430, binding = 2) buffer Entries { uint entries[]; };  // counts, then their prefix sums
layout(std430, binding = 3) buffer Samples { Tested tested[]; };
layout(std430, binding = 4) buffer ChangeMarks { uint change_marks[]; };  // per sample, then prefix sums
layout(std430, binding = 5) buffer RunMarks { uint run_marks[]; };        // 2 per sample, then prefix sums
layout(std430, binding = 6) buffer Changes { dvec2 changes[]; };          // (located s, turns visible)
layout(std430, binding = 7) writeonly buffer Runs { Run runs[]; };

uniform uint capacity;  // samples the buffers hold
// Where entries[] holds, past the most entries the table holds, the indirect dispatches over
// the samples (slots_at) and their run slots (+ 3), how many runs STEP_RUNS listed (+ 6),
// where the stroke steps read it, and the first round's samples (+ 7).
uniform uint slots_at;

// The first round's samples: the prefix sum after the last entry (the table's header counts
// the paths and entries, strokes/window_paths.glsl).
uint sample_total() { return entries[entry_count]; }
uniform float step_px, width, height;  // the parameter (a float) and the window's size: exact as doubles

const double kMargin = 4.0lf;     // px around the window where samples are taken (the test reaches 2)
const double kLocatedPx = 1.0lf;  // Kalnins et al. 2002, §4.1: a change is located within 1 px

uint entry_end(uint p) { return p + 1u < path_count ? paths[p + 1u].first_entry : entry_count; }

// Path p's first sample and the one after its last, within the buffers (where the samples
// outgrow them, those past them are not taken).
uvec2 sample_range(uint p) {
  return min(uvec2(entries[paths[p].first_entry], entries[entry_end(p)]), uvec2(capacity));
}

// Segment k's first-round samples: where it enters the margin, the multiples of the step
// from there up to where it leaves (one at the segment's end belongs to the next), and that.
struct Stretch {
  double u, v;  // in arc length
  uint first_multiple, multiples;
  bool enters, leaves;
};

bool stretch_of(Path p, uint k, out Stretch st) {
  Point a = point(p, k), b = point(p, k + 1u);
  double length = distance(a.window, b.window), t0, t1;
  if (!clip_to_window(a.window, b.window, dvec2(width, height), kMargin, t0, t1)) return false;
  st.enters = t0 > 0.0lf, st.leaves = t1 < 1.0lf;
  // A segment that does not leave ends where the next one starts, at the next point's arc
  // length (a closed path's last one at its length): a.s + length may round elsewhere,
  // and a multiple of the step between the two would go to neither segment, or to both.
  double end = k + 1u < p.points ? b.s : p.length_px;
  st.u = a.s + t0 * length, st.v = st.leaves ? a.s + t1 * length : end;
  double step = double(step_px), lo = st.enters ? floor(st.u / step) + 1.0lf : ceil(st.u / step);
  double hi = ceil(min(st.v, p.length_px) / step) - 1.0lf;  // the last multiple below v and the length
  st.first_multiple = uint(max(lo, 0.0lf));
  st.multiples = hi >= lo ? uint(hi - lo) + 1u : 0u;
  return true;
}

uint count_of(Stretch st) { return st.multiples + (st.enters ? 1u : 0u) + (st.leaves ? 1u : 0u); }

// The sample of path p at arc length s on its segment k, t along it: its window position
// rounded to float for the test only, as common/strokes/visibility.cpp sample_at rounds it.
Sample sample_on(Path p, uint k, double t, double s) {
  Point a = point(p, k), b = point(p, k + 1u);
  Sample v;
  v.window = vec2(a.window + t * (b.window - a.window));
  v.kind = p.kind & 15u;
  v.key = p.key;
  v.faces[0] = a.faces.x, v.faces[1] = a.faces.y;
  if (v.kind == 2u) v.faces[0] = t < 0.5lf ? a.faces.x : a.faces.y, v.faces[1] = 0u;  // the nearer end's face
  v.byte_value = 0u;
  if (v.kind == 1u && p.length_px > 0.0lf)
    v.byte_value = uint(clamp(floor(255.0lf * wrapped(p, s) / p.length_px), 0.0lf, 255.0lf));
  v.byte_window = p.byte_window;
  return v;
}

// The sample at arc length s, wrapped (common/strokes/visibility.cpp sample_at), tested.
bool visible_at(Path p, double s) {
  s = wrapped(p, s);
  uint k = segment_at(p, s);
  return sample_visible(sample_on(p, k, along(p, k, s), s));
}

// An open path's end is sampled after its segments' samples; a path none of whose segments
// took one gets s = 0, and its end only where it has a length.
bool has_end_sample(Path p) { return !is_closed(p) && (p.sampled != 0u || p.length_px > 0.0lf); }

void put(uint at, uint path, Path p, uint k, double s) {
  if (at >= capacity) return;  // samples past the buffers are not taken
  tested[at] = Tested(s, 0.0lf, sample_visible(sample_on(p, k, along(p, k, s), s)) ? 1u : 0u, path);
}

#if defined(STEP_CHANGES)  // Kalnins et al. 2002, §4.1: bisected until located within 1 px
void at_sample(uint i) {
  Tested a = tested[i];
  Path p = paths[a.path];
  uvec2 range = sample_range(a.path);
  uint next = i + 1u < range.y ? i + 1u : (is_closed(p) && range.y - range.x > 1u ? range.x : ~0u);
  bool changes = next != ~0u && (tested[next].flags & 1u) != (a.flags & 1u);
  change_marks[i] = changes ? 1u : 0u;
  if (!changes) return;
  double s0 = a.s, s1 = tested[next].s + (next < i ? p.length_px : 0.0lf);
  bool v0 = (a.flags & 1u) != 0u;
  while (s1 - s0 > kLocatedPx) {
    double mid = (s0 + s1) / 2.0lf;
    if (visible_at(p, mid) == v0) s0 = mid; else s1 = mid;
  }
  tested[i].flags = a.flags | 2u | (v0 ? 0u : 4u);
  tested[i].change = (s0 + s1) / 2.0lf;
}
#elif defined(STEP_MARKS)
void at_sample(uint i) {
  Tested a = tested[i];
  if ((a.flags & 2u) != 0u) changes[change_marks[i]] = dvec2(a.change, (a.flags & 4u) != 0u ? 1.0lf : 0.0lf);
  uvec2 range = sample_range(a.path);
  bool unchanged = change_marks[range.x] == change_marks[range.y];
  bool head = i == range.x && (a.flags & 1u) != 0u && (!is_closed(paths[a.path]) || unchanged);
  run_marks[2u * i] = head ? 1u : 0u;
  run_marks[2u * i + 1u] = (a.flags & 4u) != 0u ? 1u : 0u;
}
#elif defined(STEP_RUNS)
void at_slot(uint i) {  // slot i % 2 of sample i / 2
  if (run_marks[i] == run_marks[i + 1u]) return;
  uint at = i / 2u, path = tested[at].path;
  Path p = paths[path];
  uvec2 range = sample_range(path);
  uint c_first = change_marks[range.x], c_end = change_marks[range.y];
  Run r = Run(path, 0u, 0.0lf, p.length_px);
  if (i % 2u == 0u && is_closed(p)) {
    r.flags = 1u;  // visible all around
  } else if (i % 2u == 0u) {  // an open path visible from its start
    if (c_first < c_end) r.s1 = changes[c_first].x, r.flags = 4u;
  } else {
    uint c = change_marks[at];
    r.s0 = changes[c].x, r.flags = 2u;
    if (c + 1u < c_end) r.s1 = changes[c + 1u].x, r.flags |= 4u;
    else if (is_closed(p)) r.s1 = changes[c_first].x + p.length_px, r.flags |= 4u;
  }
  runs[run_marks[i]] = r;
}
#endif

void main() {
  uint i = row_index();  // STEP_COUNT, STEP_SAMPLES: an entry; STEP_ENDS: a path
#if defined(STEP_COUNT)
  if (i >= entry_count) return;
  uint path = path_of_entry(i), k = i - paths[path].first_entry;
  Stretch st;
  uint n = k < segments(paths[path]) && stretch_of(paths[path], k, st) ? count_of(st) : 0u;
  entries[i] = n;
  if (n > 0u) atomicOr(paths[path].sampled, 1u);
#elif defined(STEP_ENDS)
  if (i >= path_count) return;
  Path p = paths[i];
  entries[entry_end(i) - 1u] = (has_end_sample(p) ? 1u : 0u) + (p.sampled == 0u ? 1u : 0u);
#elif defined(STEP_SAMPLES)
  if (i >= entry_count) return;
  uint path = path_of_entry(i), k = i - paths[path].first_entry, at = entries[i];
  Path p = paths[path];
  if (k == segments(p)) {  // the end entry
    if (p.sampled == 0u) put(at++, path, p, 0u, 0.0lf);
    if (has_end_sample(p)) put(at, path, p, p.points - 2u, p.length_px);
    return;
  }
  Stretch st;
  if (!stretch_of(p, k, st)) return;
  if (st.enters) put(at++, path, p, k, st.u);
  for (uint m = 0u; m < st.multiples; ++m) put(at++, path, p, k, double(st.first_multiple + m) * double(step_px));
  if (st.leaves) put(at, path, p, k, st.v);
#elif defined(STEP_ARGS)  // one invocation: the dispatches over the samples and over their run slots
  if (gl_GlobalInvocationID.x != 0u) return;
  uint n = min(sample_total(), capacity);
  for (uint k = 0u; k < 6u; ++k) entries[slots_at + k] = 1u;  // (x, 1, 1) twice
  entries[slots_at] = clamp((n + 63u) / 64u, 1u, 65535u);
  entries[slots_at + 3u] = clamp((2u * n + 63u) / 64u, 1u, 65535u);
  entries[slots_at + 7u] = sample_total();
#elif defined(STEP_RUNS)  // each invocation every (groups x 64)th slot; the first also the runs' count
  uint slots = 2u * min(sample_total(), capacity);
  if (gl_GlobalInvocationID.x == 0u) entries[slots_at + 6u] = run_marks[slots];
  for (uint j = gl_GlobalInvocationID.x; j < slots; j += gl_NumWorkGroups.x * 64u) at_slot(j);
#else  // STEP_CHANGES, STEP_MARKS: each invocation every (groups x 64)th sample
  for (uint j = gl_GlobalInvocationID.x; j < min(sample_total(), capacity); j += gl_NumWorkGroups.x * 64u)
    at_sample(j);
#endif
}
#endif
