// The ID image's lines (Kalnins et al. 2002, §4.6; common/strokes/id_image.hpp rules 2 and 3)
// from the window paths' table (strokes/window_paths.glsl): per entry, the quads it draws
// (common/strokes/id_image.cpp add_path), in double as the reference makes them. Included
// by the counting steps (strokes/id_lines.comp) and the geometry shader that expands each
// quad (strokes/id_lines.geom).
#define PATHS_BINDING 0
#define POINTS_BINDING 1
#include "strokes/window_paths.glsl"

// Per entry, its quads; their exclusive prefix sums, the total after the last entry; then,
// from commands_at (past the most entries the table holds), the draws' commands
// (DrawArraysIndirectCommand).
layout(std430, binding = 2) buffer Pieces { uint pieces[]; };

uniform float width, height, near;  // the window's size and the near plane: exact as doubles
uniform float crease_px, crease_bias, silhouette_px, silhouette_bias, silhouette_lift;  // strokes.id_* parameters

const uint kSilhouette = 1u;              // SampleKind
const double kSilhouettePiecePx = 1.0lf;  // common/strokes/id_image.cpp: a silhouette's quads' length

bool silhouette(Path p) { return (p.kind & 15u) == kSilhouette; }

// Entry k of path p: how many quads segment k draws, over [t0, t1] of it. A crease's or
// border's one whole; a silhouette's the part that can cover a pixel center, cut into equal
// pieces at most 1 px long; none for the end entry and for paths the ID image leaves out.
uint quads_of(Path p, uint k, out double t0, out double t1) {
  t0 = 0.0lf, t1 = 1.0lf;
  if ((p.kind & kPathInIds) == 0u || k >= segments(p)) return 0u;
  if (!silhouette(p)) return 1u;
  dvec2 a = point(p, k).window, b = point(p, k + 1u).window;
  if (!clip_to_window(a, b, dvec2(width, height), double(silhouette_px) / 2.0lf + 1.0lf, t0, t1)) return 0u;
  return max(1u, uint(ceil((t1 - t0) * distance(a, b) / kSilhouettePiecePx)));
}

// The entry holding quad q: the last whose prefix sum is at most q.
uint entry_of_quad(uint q) {
  uint lo = 0u, hi = entry_count;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (pieces[mid] <= q) lo = mid; else hi = mid;
  }
  return lo;
}
