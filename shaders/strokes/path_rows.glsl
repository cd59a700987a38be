// What the GPU's window-path steps share (shaders/strokes/crease_rows.comp,
// silhouette_rows.comp, decal_rows.comp), after strokes/window_paths.glsl: what they count
// (strokes/row_counts.glsl), and, where the includer defines window_of, depth_of, world_of,
// faces_of and pressure_of for its points (and ROWS), how a piece is measured and written.
#include "strokes/row_counts.glsl"

// Adds v >= 0 to sum `value` of style `style`, carrying where the low word wraps.
void add_to_sum(uint style, uint value, double v) {
  uint i = 2u * (4u * style + value);
  double high = floor(v / 4294967296.0lf);
  uint low = uint(v - high * 4294967296.0lf), before = atomicAdd(sums[i], low);
  atomicAdd(sums[i + 1u], uint(high) + (before + low < before ? 1u : 0u));
}

const double kMargin = 4.0lf;  // common/strokes/visibility.cpp kWindowMargin

// A kept piece's bounds (common/strokes/visibility.hpp first_round_bound, length_in_margin;
// gpu/strokes/window_paths.hpp RunBound) added to its style's sums: its `count` points from
// window_of(first), which the includer defines (after strokes/window_paths.glsl), in a window
// of `size`, sampled every `step` px.
void add_bounds(uint style, uint first, uint count, bool closed, dvec2 size, double step) {
  double bound = 3.0lf, inside = 0.0lf;
  const double clear_by = kMargin - 1e-3lf;  // clear of the margin's edges by more than rounding
  for (uint k = 0u; k < (closed ? count : count - 1u); ++k) {
    dvec2 a = window_of(first + k), b = window_of(first + (k + 1u) % count);
    double t0, t1;
    if (!clip_to_window(a, b, size, kMargin, t0, t1)) continue;
    double along = (t1 - t0) * distance(a, b);
    bool clear = all(greaterThan(min(a, b), dvec2(-clear_by))) && all(lessThan(max(a, b), size + clear_by));
    bound += along / step + (clear ? 2.0lf : 4.0lf);
    inside += along;
  }
  double runs = floor(bound / 2.0lf) + 1.0lf;
  add_to_sum(style, 0u, ceil(bound));
  add_to_sum(style, 1u, runs);
  add_to_sum(style, 2u, ceil(inside + runs));
  add_to_sum(style, 3u, double(count) + 2.0lf * runs);
}

#if defined(ROWS)
// Writes a piece's points' rows (PathBuilder::flush: window arc lengths from 0) from point
// `first` of `count`, to the table's points from `at` + first; returns its length.
double write_points(uint first, uint count, bool closed, uint at) {
  double s = 0.0lf;
  for (uint k = 0u; k < count; ++k) {
    uint q = first + k, next = first + (k + 1u) % count;
    bool segment = closed || k + 1u < count;
    Point row;
    row.window = window_of(q), row.s = s, row.pressure = pressure_of(q), row.depth = depth_of(q);
    row.faces = segment ? faces_of(q) : uvec2(0u);
    row.world_step = segment ? distance(world_of(q), world_of(next)) : 0.0lf;
    row.pad = 0.0lf;
    path_points[at + q] = row;
    if (k + 1u < count) s += distance(window_of(q), window_of(next));
  }
  return closed ? s + distance(window_of(first + count - 1u), window_of(first)) : s;
}
#endif
