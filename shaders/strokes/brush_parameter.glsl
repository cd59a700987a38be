// A brush parameter (Kalnins et al. 2003; common/strokes/base_stroke.hpp BrushParameter):
// `count` knots (s, t) from `first`, s ascending (two knots at one s: t jumps there), read by
// brush_knot(i), which the includer defines.

// t at arc length s: linear between knots, extrapolated along the end intervals; with fewer
// than 2 knots, s itself (common/strokes/base_stroke.cpp brush_t).
double brush_t_at(uint first, uint count, double s) {
  if (count < 2u) return s;
  uint below = 0u;  // knots with x <= s
  for (uint lo = 0u, hi = count; lo < hi;) {
    uint mid = (lo + hi) / 2u;
    if (brush_knot(first + mid).x <= s) lo = below = mid + 1u; else hi = mid;
  }
  uint k = clamp(below, 1u, count - 1u) - 1u;
  dvec2 a = brush_knot(first + k), b = brush_knot(first + k + 1u);
  return b.x > a.x ? a.y + (s - a.x) * (b.y - a.y) / (b.x - a.x) : b.y;  // two knots at one s: a jump
}
