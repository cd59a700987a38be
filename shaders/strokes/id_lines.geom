#version 450 core
// The ID image's lines (common/strokes/id_image.hpp rules 2 and 3): each quad, one point in
// (strokes/id_lines.vert), placed from the window paths' table (strokes/id_lines.glsl) as
// common/strokes/id_image.cpp IdTriangles::segment places it: `width` px wide along its
// piece of segment, at depth d (1 - bias), rounded to float, as the same two triangles. z =
// near / d is interpolated affinely (noperspective) and written as the fragment's depth
// (strokes/id_image.frag). Once per quad: a vertex shader would place each corner six times.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;

#include "strokes/id_lines.glsl"

flat in uint quad[];
noperspective out float z_line;
flat out uint key;

uniform vec2 window_size;

// The piece of segment k of path p a quad covers: its ends, their depths and its key.
struct Piece {
  dvec2 a, b;
  double da, db;
  uint key;
  double lift;  // nearer by at least this (a silhouette: its segment's world length times silhouette_lift)
};

Piece piece_of(Path p, uint k, uint i) {
  Point from = point(p, k), to = point(p, k + 1u);
  if (!silhouette(p)) return Piece(from.window, to.window, from.depth, to.depth, p.key, 0.0lf);
  double t0, t1;
  uint n = quads_of(p, k, t0, t1);
  double u0 = t0 + (t1 - t0) * double(i) / double(n), u1 = t0 + (t1 - t0) * double(i + 1u) / double(n);
  dvec2 a = from.window, b = to.window;
  double length = distance(a, b), inv_a = 1.0lf / from.depth, inv_b = 1.0lf / to.depth;
  // The key of its midpoint's arc length s: key << 8 | floor(255 s / L); 1/d is affine in the window.
  double s_mid = from.s + length * (u0 + u1) / 2.0lf;
  double byte = p.length_px > 0.0lf ? floor(255.0lf * s_mid / p.length_px) : 0.0lf;
  return Piece(a + u0 * (b - a), a + u1 * (b - a), 1.0lf / ((1.0lf - u0) * inv_a + u0 * inv_b),
               1.0lf / ((1.0lf - u1) * inv_a + u1 * inv_b), p.key << 8 | uint(clamp(byte, 0.0lf, 255.0lf)),
               double(silhouette_lift) * from.world_step);
}

void emit(dvec2 at, double d, uint piece_key) {
  double near_d = double(near);
  gl_Position = vec4(vec2(at) / window_size * 2.0 - 1.0, 0.0, 1.0);
  z_line = float(near_d / max(d, near_d));
  key = piece_key;
  EmitVertex();
}

void main() {
  uint q = quad[0], e = entry_of_quad(q);
  Path p = paths[path_of_entry(e)];
  Piece piece = piece_of(p, e - p.first_entry, q - pieces[e]);
  dvec2 along = piece.b - piece.a;
  double length = sqrt(along.x * along.x + along.y * along.y);
  if (!(length > 0.0lf)) return;
  double width = double(silhouette(p) ? silhouette_px : crease_px);
  double keep = 1.0lf - double(silhouette(p) ? silhouette_bias : crease_bias);
  dvec2 n = dvec2(-along.y, along.x) / length * (width / 2.0lf);
  double da = min(piece.da * keep, piece.da - piece.lift), db = min(piece.db * keep, piece.db - piece.lift);
  dvec2 corners[4] = dvec2[4](piece.a - n, piece.a + n, piece.b + n, piece.b - n);
  // The reference's two triangles, (0, 1, 2) and (0, 2, 3), as one strip: 4 vertices, not 6.
  const int order[4] = int[4](1, 0, 2, 3);
  for (int v = 0; v < 4; ++v) emit(corners[order[v]], order[v] < 2 ? da : db, piece.key);
  EndPrimitive();
}
