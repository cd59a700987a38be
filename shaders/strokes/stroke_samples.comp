#version 450 core
// Stroke samples on the GPU (Kalnins et al. 2002, §4.1, §4.3): steps 1.-5. of
// common/strokes/base_stroke.hpp, in double as the reference makes them, one invocation per
// visible run. STEP_COUNT keeps the run's distinct points and counts its samples; after a
// prefix sum over the counts, STEP_WRITE writes them, and their ribbons' normals, where
// shaders/strokes/common_ribbon.glsl reads them; STEP_ARGS writes the indirect draw of their
// ribbons (six vertices a sample).
layout(local_size_x = 64) in;

#include "strokes/stroke_runs.glsl"
layout(std430, binding = 10) readonly buffer RunArgs { uint run_args[4]; };  // the dispatch over the runs, their count

layout(std430, binding = 2) readonly buffer RunsIn { RunIn runs_in[]; };
layout(std430, binding = 3) readonly buffer Points { dvec2 points[]; };
layout(std430, binding = 4) readonly buffer Offsets { Offset offsets[]; };
// Per run listed: its sample count, then (scanned) its first sample; the total after them.
layout(std430, binding = 5) buffer Counts { uint counts[]; };
// Each run's distinct points, at its first_point.
layout(std430, binding = 6) buffer Distinct { dvec2 distinct[]; };
// Per run: the length of its spline (2.) and how many distinct points it kept.
struct RunState {  // gpu/strokes/stroke_samples.cpp RunState
  double length;
  uint distinct_count, pad;
};
layout(std430, binding = 7) buffer RunStates { RunState states[]; };

uniform uint run_count, capacity;  // run_count: the rows of counts[] less one

const double kSamePoint = 1e-6lf, kPiecesPerPx = 4.0lf, kSameArcLength = 1e-9lf, kNearPenChange = 0.05lf;
const double kDegenerate = 1e-9lf;
const int kMinPieces = 4, kMaxPieces = 4096;

bool finite(dvec2 p) { return !any(isnan(p)) && !any(isinf(p)); }

// 1. The run's finite points, repeats merged, a closed run's last point equal to its first
// dropped: kept in `distinct` at its first_point.
uint keep_distinct_points(RunIn r) {
  uint n = 0u;
  for (uint k = 0u; k < r.point_count; ++k) {
    dvec2 p = points[r.first_point + k];
    if (finite(p) && (n == 0u || distance(distinct[r.first_point + n - 1u], p) > kSamePoint))
      distinct[r.first_point + n++] = p;
  }
  if ((r.flags & kClosed) != 0u && n > 1u &&
      distance(distinct[r.first_point], distinct[r.first_point + n - 1u]) <= kSamePoint)
    --n;
  return n;
}

// A cubic Hermite span: p(t) = h00 p0 + h10 m0 + h01 p1 + h11 m1, t in [0, 1].
struct Span {
  dvec2 p0, m0, p1, m1;
};

dvec2 span_at(Span s, double t) {
  double t2 = t * t, t3 = t2 * t;
  return (2.0lf * t3 - 3.0lf * t2 + 1.0lf) * s.p0 + (t3 - 2.0lf * t2 + t) * s.m0 + (-2.0lf * t3 + 3.0lf * t2) * s.p1 +
         (t3 - t2) * s.m1;
}

// Length of the Bézier control polygon p0, p0 + m0/3, p1 - m1/3, p1.
double control_length(Span s) {
  return length(s.m0) / 3.0lf + distance(s.p0 + s.m0 / 3.0lf, s.p1 - s.m1 / 3.0lf) + length(s.m1) / 3.0lf;
}

// The run's curve: its distinct points, their count, closed.
struct Curve {
  uint first, n;
  bool closed;
};

dvec2 point(Curve c, uint i) { return distinct[c.first + i % c.n]; }

// v_i = (p_{i+1} - p_{i-1}) / (|p_{i+1} - p_i| + |p_i - p_{i-1}|): the tangent per px of chord.
dvec2 velocity(Curve c, uint i) {
  dvec2 prev = point(c, i + c.n - 1u), here = point(c, i), next = point(c, i + 1u);
  return (next - prev) / (distance(next, here) + distance(here, prev));
}

uint span_count(Curve c) { return c.closed ? c.n : c.n - 1u; }

// Span i of the non-uniform Catmull-Rom spline, with parabolic end slopes when open.
Span span(Curve c, uint i) {
  dvec2 a = point(c, i), b = point(c, i + 1u);
  if (c.n == 2u) return Span(a, b - a, b, b - a);
  double d = distance(a, b);
  bool first_span = !c.closed && i == 0u, last_span = !c.closed && i + 1u == span_count(c);
  dvec2 m0 = first_span ? dvec2(0.0lf) : velocity(c, i) * d;
  dvec2 m1 = last_span ? dvec2(0.0lf) : velocity(c, i + 1u) * d;
  if (first_span) m0 = 2.0lf * (b - a) - m1;  // parabolic end slopes
  if (last_span) m1 = 2.0lf * (b - a) - m0;
  return Span(a, m0, b, m1);
}

int pieces(Span s) { return int(clamp(ceil(kPiecesPerPx * control_length(s)), double(kMinPieces), double(kMaxPieces))); }

// 2. A walk along the dense polyline of the spline: the piece [a, b] from arc length sa to sb.
struct Walk {
  Curve c;
  uint span_index;
  int k, m;
  Span s;
  dvec2 a, b;
  double sa, sb;
  bool last;  // b is the curve's last dense point
};

// Moves the walk one piece on; false at the end of the curve.
bool step(inout Walk w) {
  if (w.k == w.m) {
    if (w.span_index + 1u == span_count(w.c)) return false;
    w.s = span(w.c, ++w.span_index);
    w.m = pieces(w.s);
    w.k = 0;
  }
  ++w.k;
  w.a = w.b, w.sa = w.sb;
  w.b = span_at(w.s, double(w.k) / double(w.m));
  w.sb = w.sa + distance(w.a, w.b);
  w.last = w.k == w.m && w.span_index + 1u == span_count(w.c);
  return true;
}

Walk start_walk(Curve c) {
  Walk w;
  w.c = c;
  w.span_index = 0u;
  w.s = span(c, 0u);
  w.m = pieces(w.s);
  w.k = 0;
  w.b = w.s.p0, w.sb = 0.0lf;
  step(w);
  return w;
}

double curve_length(Curve c) {
  Walk w = start_walk(c);
  while (step(w)) {}
  return w.sb;
}

// The point at arc length `at` (nondecreasing from call to call), linear between dense points.
dvec2 point_at(inout Walk w, double at) {
  while (w.sb <= at && !w.last) step(w);
  double piece = w.sb - w.sa;
  return piece > 0.0lf ? mix(w.a, w.b, (at - w.sa) / piece) : w.a;
}

// The length of the polyline through the run's distinct points (a loop's closing segment
// first, as the reference sums it).
double polyline_length(Curve c) {
  double length = c.closed ? distance(point(c, c.n - 1u), point(c, 0u)) : 0.0lf;
  for (uint j = 0u; j + 1u < c.n; ++j) length += distance(point(c, j), point(c, j + 1u));
  return length;
}

// 6. The run's brush parameter (Kalnins et al. 2003): knots (s, t) over its polyline's arc
// length, kept after its points; with fewer than 2, t = s.
dvec2 brush_knot(uint i) { return points[i]; }
#include "strokes/brush_parameter.glsl"
dvec2 knot(RunIn r, uint k) { return points[r.first_point + r.point_count + k]; }
bool has_brush(RunIn r) { return r.knot_count >= 2u; }
double brush_t(RunIn r, double s) { return brush_t_at(r.first_point + r.point_count, r.knot_count, s); }

bool repeats(RunIn r) { return (r.flags & kRepeats) != 0u; }

// 4. Where the offsets are stamped: at the brush parameter t(s) where the run has one and the
// example repeats, else at s. per_spline: the polyline's arc length per px of the spline's.
struct Stamp {
  bool brushed;
  double per_spline;
};

Stamp stamp_of(RunIn r, Curve c, double length) {
  bool brushed = has_brush(r) && repeats(r);
  return Stamp(brushed, has_brush(r) ? polyline_length(c) / length : 1.0lf);
}

double stamp_at(RunIn r, Stamp st, double s) { return st.brushed ? brush_t(r, s * st.per_spline) : s; }

// 4. The arc lengths where the pen lifts or lands, in increasing order: the ends of each lift
// of nonzero length, (k + t_i) L_drawn to (k + t_next) L_drawn, in every period k (an example
// that does not repeat: k = 0, and a lift from its last offset does not end), kept in
// [kNearPenChange, L - kNearPenChange]. Under a brush parameter, each linear piece of t in
// turn (the first and last extended, brush_t's) gives the arc lengths where t takes them,
// its periods walked the way t runs, so that s increases.
const double kInfinite = 1e300lf;

struct Changes {
  RunIn r;
  Stamp stamp;
  double length;
  uint piece, pieces;  // the pieces of t (t = s: one)
  dvec2 a, b;          // the piece's line through (s, t) points; [from, to) its polyline arc lengths
  double from, to;
  int k, k_end, dir;   // its periods, from k to k_end in steps of dir
  uint i, e;           // the offset; the lift's end, counted in the walk's direction
};

uint first_offset_walked(Changes c) { return c.dir > 0 ? 0u : c.r.offset_count - 1u; }

// Starts piece p (or the next that has one) of the walk; c.piece == c.pieces when none is left.
void start_piece(inout Changes c, uint p) {
  for (c.piece = p; c.piece < c.pieces; ++c.piece) {
    double lo = 0.0lf, hi = c.length;  // t over the piece's part of [0, L]
    if (c.stamp.brushed) {
      c.a = knot(c.r, c.piece), c.b = knot(c.r, c.piece + 1u);
      if (!(c.b.x > c.a.x) || c.b.y == c.a.y) continue;  // a jump, or flat: no crossing
      c.from = c.piece == 0u ? -kInfinite : c.a.x, c.to = c.piece + 1u == c.pieces ? kInfinite : c.b.x;
      double x0 = max(c.from, 0.0lf), x1 = min(c.to, c.length * c.stamp.per_spline);
      if (!(x1 > x0)) continue;
      double t0 = c.a.y + (x0 - c.a.x) * (c.b.y - c.a.y) / (c.b.x - c.a.x);
      double t1 = c.a.y + (x1 - c.a.x) * (c.b.y - c.a.y) / (c.b.x - c.a.x);
      lo = min(t0, t1), hi = max(t0, t1);
    } else {
      c.a = dvec2(0.0lf), c.b = dvec2(1.0lf), c.from = -kInfinite, c.to = kInfinite;
    }
    int first = repeats(c.r) ? int(floor(lo / c.r.example_length)) - 1 : 0;
    int last = repeats(c.r) ? int(floor(hi / c.r.example_length)) : 0;
    c.dir = c.b.y > c.a.y ? 1 : -1;
    c.k = c.dir > 0 ? first : last, c.k_end = c.dir > 0 ? last : first;
    c.i = first_offset_walked(c), c.e = 0u;
    return;
  }
}

Changes start_changes(RunIn r, Curve curve, double length) {
  Changes c;
  c.r = r, c.stamp = stamp_of(r, curve, length), c.length = length;
  c.pieces = r.offset_count == 0u ? 0u : c.stamp.brushed ? r.knot_count - 1u : 1u;
  start_piece(c, 0u);
  return c;
}

// The arc length where the piece's t is `t`, or a negative number outside the piece.
double piece_arc_length(Changes c, double t) {
  double x = c.a.x + (t - c.a.y) * (c.b.x - c.a.x) / (c.b.y - c.a.y);
  return x >= c.from && x < c.to ? (c.stamp.brushed ? x / c.stamp.per_spline : x) : -1.0lf;
}

// The next change, or a negative number when there is none.
double next_change(inout Changes c) {
  while (c.piece < c.pieces) {
    for (; c.dir > 0 ? c.k <= c.k_end : c.k >= c.k_end; c.k += c.dir, c.i = first_offset_walked(c)) {
      for (; c.i < c.r.offset_count; c.i += uint(c.dir), c.e = 0u) {
        Offset o = offsets[c.r.first_offset + c.i];
        bool last = c.i + 1u == c.r.offset_count;
        double next_t = !last ? offsets[c.r.first_offset + c.i + 1u].t : offsets[c.r.first_offset].t + 1.0lf;
        if (o.pen_up == 0u || !(next_t > o.t)) continue;
        uint ends = last && !repeats(c.r) ? 1u : 2u;  // a held last lift does not end
        for (; c.e < ends; ++c.e) {
          uint end = c.dir > 0 ? c.e : ends - 1u - c.e;
          double s = piece_arc_length(c, (double(c.k) + (end == 0u ? o.t : next_t)) * c.r.example_length);
          if (s > 0.0lf && s < c.length && s >= kNearPenChange && s <= c.length - kNearPenChange) {
            ++c.e;
            return s;
          }
        }
      }
    }
    start_piece(c, c.piece + 1u);
  }
  return -1.0lf;
}

// 3. and 4.: the even samples k L / n, n = ceil(L / sample_px), merged with the pen changes
// in increasing order; an even sample within kNearPenChange of a change gives way to it, and
// arc lengths within kSameArcLength of the last one kept are one.
struct Merge {
  double length;
  int n, k;
  Changes changes;
  double previous_change, next_change, last;
  bool any;
};

Merge start_merge(RunIn r, Curve c, double length) {
  Merge m;
  m.length = length;
  m.n = max(1, int(ceil(length / double(r.sample_px) - 1e-9lf)));
  m.k = 0;
  m.changes = start_changes(r, c, length);
  m.previous_change = -1.0lf;
  m.next_change = next_change(m.changes);
  m.any = false;
  return m;
}

// The next sample's arc length, or a negative number after the last.
double next_sample(inout Merge m) {
  for (;;) {
    double even = m.k <= m.n ? m.length * double(m.k) / double(m.n) : -1.0lf;
    bool change_first = m.next_change >= 0.0lf && (even < 0.0lf || m.next_change < even);
    double s;
    if (change_first) {
      s = m.next_change;
      m.previous_change = s;
      m.next_change = next_change(m.changes);
    } else {
      if (even < 0.0lf) return -1.0lf;
      ++m.k;
      bool near = (m.previous_change >= 0.0lf && m.previous_change >= even - kNearPenChange) ||
                  (m.next_change >= 0.0lf && m.next_change < even + kNearPenChange);
      if (even > 0.0lf && even < m.length && near) continue;
      s = even;
    }
    if (m.any && s - m.last < kSameArcLength) continue;
    m.any = true;
    m.last = s;
    return s;
  }
}

Curve curve_of(RunIn r, uint distinct_count) {
  return Curve(r.first_point, distinct_count, (r.flags & kClosed) != 0u && distinct_count >= 3u);
}

#ifdef STEP_COUNT
void at_run(uint run) {
  RunIn r = runs_in[run];
  uint n = keep_distinct_points(r);
  uint count = 0u;
  Curve c = curve_of(r, n);
  double L = n >= 2u ? curve_length(c) : 0.0lf;
  if (n >= 2u) {
    Merge m = start_merge(r, c, L);
    while (next_sample(m) >= 0.0lf) ++count;
  }
  states[run] = RunState(L, n, 0u);
  counts[run] = count;
}
#endif

#ifdef STEP_ARGS
layout(std430, binding = 8) writeonly buffer Draw { uint draw[4]; };  // DrawArraysIndirectCommand
void main() { draw = uint[4](6u * min(counts[run_args[3]], capacity), 1u, 0u, 0u); }
#endif

#ifdef STEP_WRITE
#define RIBBON_NORMALS
#include "strokes/common_ribbon.glsl"
// Per sample: its point on the base curve, the base curve's normal there, its arc length.
struct Base {
  dvec2 point, normal;
  double s, pad;
};
layout(std430, binding = 9) buffer Bases { Base bases[]; };

// 4. The rubber stamp: the example's offset at arc length s, interpolated linearly at
// t = (s mod L_drawn) / L_drawn, wrapping from its last offset to its first; an example that
// does not repeat holds t = s / L_drawn in [0, 1].
struct Stamped {
  double displacement, pressure;
  bool pen_down;
};

Stamped rubber_stamp(RunIn r, double s, double run_length) {
  if (r.offset_count == 0u) return Stamped(0.0lf, 1.0lf, true);
  double t = s / r.example_length;
  double scale = (r.flags & kUnscaled) != 0u ? 1.0lf : min(run_length / r.example_length, 1.0lf);
  t = repeats(r) ? t - floor(t) : clamp(t, 0.0lf, 1.0lf);
  uint count = 0u;  // offsets with t_i <= t (they are sorted)
  for (uint lo = 0u, hi = r.offset_count; lo < hi;) {
    uint mid = (lo + hi) / 2u;
    if (offsets[r.first_offset + mid].t <= t) lo = count = mid + 1u; else hi = mid;
  }
  if (!repeats(r) && (count == 0u || count == r.offset_count)) {  // held before the first offset, after the last
    Offset held = offsets[r.first_offset + (count == 0u ? 0u : r.offset_count - 1u)];
    return Stamped(held.displacement * scale, held.pressure, count == 0u || held.pen_up == 0u);
  }
  if (count == 0u) t += 1.0lf;  // before the first offset: on the last segment, from the period before
  uint i = (count + r.offset_count - 1u) % r.offset_count;
  bool wraps = i + 1u == r.offset_count;
  Offset here = offsets[r.first_offset + i], next = offsets[r.first_offset + (wraps ? 0u : i + 1u)];
  double t_next = wraps ? next.t + 1.0lf : next.t;
  double f = t_next > here.t ? (t - here.t) / (t_next - here.t) : 0.0lf;
  return Stamped(mix(here.displacement, next.displacement, f) * scale, mix(here.pressure, next.pressure, f),
                 here.pen_up == 0u);
}

// 5. Width and alpha at arc length s of a run of length L.
double taper(double dl, double T) {
  double x = (T - dl) / T;
  return dl < T ? sqrt(max(0.0lf, 1.0lf - x * x)) : 1.0lf;
}
double fade(double dl, double F) {
  double x = (F - dl) / F, y = max(0.0lf, 1.0lf - x * x);
  return dl < F ? y * sqrt(y) : 1.0lf;
}
double halo_base(double dh, double H) {  // 1 - h^2
  double h = (H - dh) / H;
  return dh < H ? max(0.0lf, 1.0lf - h * h) : 1.0lf;
}

const double kFar = 1e300lf;  // px: no end caused by occlusion

dvec2 shape_at(RunIn r, double s, double L, bool has_ends, double pressure) {
  double w = double(r.width), a = double(r.alpha);
  if (has_ends) {
    double dl = max(0.0lf, min(s, L - s)), dh = kFar;
    if ((r.flags & kOccludedStart) != 0u) dh = min(dh, s);
    if ((r.flags & kOccludedEnd) != 0u) dh = min(dh, L - s);
    double halo = halo_base(dh, double(r.halo)), flare = 1.0lf + double(r.flare) * (1.0lf - 2.0lf * dl / L);
    w *= taper(dl, double(r.taper)) * flare * sqrt(sqrt(halo));
    a *= fade(dl, double(r.fade)) * (halo * halo) * (halo * halo) * halo;
  }
  if ((r.flags & kPressureWidth) != 0u) w *= pressure;
  if ((r.flags & kPressureAlpha) != 0u) a *= pressure;
  if (w < 2.0lf) return dvec2(2.0lf, a * w * w / 4.0lf);  // thin-stroke rule: drawn 2 px wide
  return dvec2(w, a);
}

dvec2 left_normal(dvec2 d) { return dvec2(-d.y, d.x); }

// The left unit normal of base segment j -> j + 1 of the run's samples [b, b + count), or
// (0, 0) when it is degenerate.
dvec2 own_normal(uint b, uint j) {
  dvec2 d = bases[b + j + 1u].point - bases[b + j].point;
  double len = length(d);
  return len > kDegenerate ? left_normal(d / len) : dvec2(0.0lf);
}

// 6.'s vertex normals on the base points (cyclic when closed): each segment's normal, a
// degenerate one the previous valid one's (the first valid one's before any), at a sample the
// normalized sum of its two segments', a hairpin the previous one's. Written into bases[].normal.
// False when no segment has a direction (the run then has no samples).
bool base_normals(uint b, uint count, bool cyclic) {
  dvec2 first_valid = dvec2(0.0lf), last_valid = dvec2(0.0lf);
  for (uint j = 0u; j + 1u < count; ++j) {
    dvec2 n = own_normal(b, j);
    if (n == dvec2(0.0lf)) continue;
    if (first_valid == dvec2(0.0lf)) first_valid = n;
    last_valid = n;
  }
  if (first_valid == dvec2(0.0lf)) return false;
  dvec2 previous = first_valid;  // segment j - 1's normal
  for (uint j = 0u; j < count; ++j) {
    dvec2 next = j + 1u < count ? own_normal(b, j) : first_valid;
    if (j + 1u < count && next == dvec2(0.0lf)) next = previous;
    bool has_prev = j > 0u || cyclic, has_next = j + 1u < count || cyclic;
    dvec2 prev = j > 0u ? previous : last_valid;
    dvec2 sum = (has_prev ? prev : dvec2(0.0lf)) + (has_next ? next : dvec2(0.0lf));
    double len = length(sum);
    bases[b + j].normal = len > 1e-9lf ? sum / len : (has_prev ? prev : next);
    if (j + 1u < count) previous = next;
  }
  return true;
}

// The run's base points at its sample arc lengths, from `b`; their count.
uint write_bases(RunIn r, Curve c, double length, uint b) {
  Merge m = start_merge(r, c, length);
  Walk w = start_walk(c);
  uint count = 0u;
  for (double s = next_sample(m); s >= 0.0lf && b + count < capacity; s = next_sample(m), ++count)
    bases[b + count] = Base(point_at(w, clamp(s, 0.0lf, length)), dvec2(0.0lf), s, 0.0lf);
  return count;
}

void at_run(uint run) {
  RunIn r = runs_in[run];
  uint b = counts[run], count = min(counts[run + 1u], capacity) - min(b, capacity);
  RunState state = states[run];
  Curve c = curve_of(r, state.distinct_count);
  double L = state.length;
  bool drawn = count >= 2u && write_bases(r, c, L, b) == count && base_normals(b, count, c.closed);
  Stamp stamp = drawn ? stamp_of(r, c, L) : Stamp(false, 1.0lf);
  bool whole = true;
  for (uint j = 0u; j < count; ++j) {
    uint at = b + j;
    if (!drawn) {
      samples[at] = Sample(vec2(0.0), 0.0, 0.0, 0.0, run, 0u, 0u, vec2(0.0));
      continue;
    }
    Base q = bases[at];
    Stamped o = rubber_stamp(r, stamp_at(r, stamp, q.s), L);
    dvec2 shape = shape_at(r, q.s, L, !c.closed, o.pressure);
    bool down = j + 1u < count && rubber_stamp(r, stamp_at(r, stamp, 0.5lf * (q.s + bases[at + 1u].s)), L).pen_down;
    whole = whole && (down || j + 1u == count);
    double t = has_brush(r) ? brush_t(r, q.s * stamp.per_spline) : q.s;  // 6.
    samples[at] = Sample(vec2(q.point + q.normal * o.displacement), float(t / double(r.period)), float(shape.x),
                         float(shape.y), run, down ? 1u : 0u, 0u, vec2(0.0));
  }
  runs[run] = Run(r.color_layer, b, drawn ? count : 0u, c.closed && whole ? 1u : 0u, 0u);
  put_ribbon_normals(run);  // 6.'s, in float, for the vertex shader
}
#endif

#if !defined(STEP_ARGS)
// Each invocation every (groups x 64)th of the runs listed: the dispatch is indirect, as
// many groups as they need (65535 at most), their count on the GPU.
void main() {
  for (uint run = gl_GlobalInvocationID.x; run < run_args[3]; run += gl_NumWorkGroups.x * 64u) at_run(run);
}
#endif
