// The window paths and visible runs as the GPU's stroke steps read them (gpu/strokes/window_paths.hpp
// PathRow, PointRow, RunRow; std430): the paths' table and points, bound at PATHS_BINDING and
// POINTS_BINDING, which the includer defines (and POINTS_ACCESS, the points' qualifier:
// readonly unless defined). Positions and arc lengths are in double, as the
// reference (common/strokes/visibility.cpp) takes them.
struct Path {
  uint first_point, points, first_entry;
  uint kind;  // SampleKind; bit 4: closed; bit 5: drawn in the ID image (common/strokes/id_image.hpp)
  uint key, byte_window;
  uint sampled;  // visibility.comp STEP_COUNT: 1 where a segment took a sample
  uint style;    // its runs' style (run_inputs.comp): crease 0, border 1, silhouette 2, decal d 3 + d
  double length_px;
  double alpha_scale, width_scale;  // a hatch's level-of-detail factors this frame (else 1)
};
struct Point {
  dvec2 window;
  double s;         // window arc length from the path's start
  uvec2 faces;      // of the segment from this point (common/strokes/strokes.hpp WindowPath::front_faces)
  double pressure;  // a decal's or hatch's drawn pressure (else 1)
  double depth;       // linear view depth
  double world_step;  // the world length of the segment from this point (0 at an open path's end)
  double pad;         // std430 rounds the struct to 16 bytes (its dvec2)
};
struct Run {
  uint path;
  uint flags;  // 1: the whole closed path; 2: occluded at its start; 4: at its end
  double s0, s1;
};

// The table's header (gpu/strokes/window_paths.hpp TableHeader), then its rows: how many paths
// and entries it holds and the first silhouette entry, written where the rows are (the CPU,
// or shaders/strokes/table_rows.comp), and the indirect dispatches over its entries and over
// its paths, (x, y, 1) groups of kRowsGroup.
layout(std430, binding = PATHS_BINDING) buffer Paths {
  uint path_count, entry_count, silhouette_entry, header_pad;
  uint over_entries[3], over_paths[3], header_pad2[2];
  Path paths[];
};
#ifndef POINTS_ACCESS
#define POINTS_ACCESS readonly
#endif
layout(std430, binding = POINTS_BINDING) POINTS_ACCESS buffer PathPoints { Point path_points[]; };

const uint kPathClosed = 16u, kPathInIds = 32u;  // Path.kind's flags

bool is_closed(Path p) { return (p.kind & kPathClosed) != 0u; }
uint segments(Path p) { return is_closed(p) ? p.points : p.points - 1u; }
Point point(Path p, uint k) { return path_points[p.first_point + k % p.points]; }

// The last path whose first entry is at most e: the path of entry e (its segments, then its
// end: gpu/strokes/window_paths.hpp PathTable).
uint path_of_entry(uint e) {
  uint lo = 0u, hi = path_count;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (paths[mid].first_entry <= e) lo = mid; else hi = mid;
  }
  return lo;
}

// A closed path's arc length s in [0, L): s is below 2 L here (a change's bisection and a run
// reach past the seam by less than L), where this is fmod's exact result.
double wrapped(Path p, double s) { return is_closed(p) && s >= p.length_px && p.length_px > 0.0lf ? s - p.length_px : s; }

// common/strokes/visibility.cpp point_at: the segment holding arc length s (wrapped), and
// where along segment k s lies.
uint segment_at(Path p, double s) {
  uint lo = 0u, hi = p.points;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (point(p, mid).s <= s) lo = mid; else hi = mid;
  }
  return is_closed(p) ? lo : min(lo, p.points - 2u);
}
double along(Path p, uint k, double s) {
  double s0 = point(p, k).s, s1 = k + 1u < p.points ? point(p, k + 1u).s : p.length_px;
  return s1 > s0 ? clamp((s - s0) / (s1 - s0), 0.0lf, 1.0lf) : 0.0lf;
}
// The window point at arc length s (a closed path wraps).
dvec2 window_at(Path p, double s) {
  s = wrapped(p, s);
  uint k = segment_at(p, s);
  dvec2 a = point(p, k).window, b = point(p, k + 1u).window;
  return a + along(p, k, s) * (b - a);
}

// The linear view depth at arc length s (a closed path wraps), perspective-correct between
// the segment's ends, as common/strokes/visibility.cpp world_at weighs its world points.
double depth_at(Path p, double s) {
  s = wrapped(p, s);
  uint k = segment_at(p, s);
  double t = along(p, k, s), wa = (1.0lf - t) / point(p, k).depth, wb = t / point(p, k + 1u).depth;
  return 1.0lf / (wa + wb);
}

// common/strokes/strokes.cpp clip_to_window: the part [t0, t1] of segment a -> b within
// `margin` px of a window of `size`.
bool clip_to_window(dvec2 a, dvec2 b, dvec2 size, double margin, out double t0, out double t1) {
  dvec2 d = b - a, lo = dvec2(-margin), hi = size + margin;
  t0 = 0.0lf, t1 = 1.0lf;
  for (int c = 0; c < 2; ++c) {
    if (d[c] == 0.0lf) {
      if (a[c] < lo[c] || a[c] > hi[c]) return false;
      continue;
    }
    double u = (lo[c] - a[c]) / d[c], v = (hi[c] - a[c]) / d[c];
    t0 = max(t0, min(u, v)), t1 = min(t1, max(u, v));
  }
  return t0 <= t1;
}
