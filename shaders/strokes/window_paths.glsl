// The window paths and visible runs as the GPU's stroke steps read them (gpu/strokes/window_paths.hpp
// PathRow, PointRow, RunRow; std430): the paths' table and points, bound at PATHS_BINDING and
// POINTS_BINDING, which the includer defines. Positions and arc lengths are in double, as the
// reference (common/strokes/visibility.cpp) takes them.
struct Path {
  uint first_point, points, first_entry;
  uint kind;  // SampleKind; bit 4: closed
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
};
struct Run {
  uint path;
  uint flags;  // 1: the whole closed path; 2: occluded at its start; 4: at its end
  double s0, s1;
};

layout(std430, binding = PATHS_BINDING) buffer Paths { Path paths[]; };
layout(std430, binding = POINTS_BINDING) readonly buffer PathPoints { Point path_points[]; };

bool is_closed(Path p) { return (p.kind & 16u) != 0u; }
Point point(Path p, uint k) { return path_points[p.first_point + k % p.points]; }

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
