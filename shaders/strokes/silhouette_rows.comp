#version 450 core
// The silhouette paths as window paths, on the GPU (Kalnins et al. 2002, §4.5): the rows of the
// frame's path table (strokes/window_paths.glsl) that common/strokes/strokes.cpp window_lines
// makes of them on the CPU, written after the creases' and borders' (crease_rows.comp), and
// the bounds the CPU sizes the later steps' buffers by, summed (strokes/path_rows.glsl). The
// steps of gpu/strokes/silhouette_rows.cpp:
//   STEP_ARGS:   one invocation: the groups over the paths;
//   STEP_PIECES: per path, the piece it keeps (its first of two points or more in front of
//                the near plane: PathBuilder::add), its entries, and its bounds;
//   STEP_ROWS:   per kept path, its row and its points' rows, placed by the prefix sums of
//                which paths are kept and of their entries;
//   STEP_TOTALS: one invocation: the paths kept and their entries.
#if defined(STEP_ARGS) || defined(STEP_TOTALS)
layout(local_size_x = 1) in;
#else
layout(local_size_x = 64) in;  // kRowsGroup
#endif
#if defined(STEP_ROWS)
#define ROWS
#endif

#include "util/common_table.glsl"

uniform sampler2D path_table;  // silhouette_paths.paths: row 0 (paths, points); 1 + p: (start + 1, first, points, flags)

struct SilhouettePoint {  // common/strokes/silhouette_paths.hpp, as shaders/strokes/silhouette_points.comp wrote them
  double x, y, depth, t;
  uint record, slot;
};
layout(std430, binding = 1) readonly buffer Points { SilhouettePoint points[]; };
layout(std430, binding = 2) readonly buffer Worlds { dvec4 worlds[]; };  // each point in world space
layout(std430, binding = 3) buffer Pieces { uvec4 pieces[]; };  // per path: (first point, points, closed, front)
layout(std430, binding = 4) buffer Kept { uint kept[]; };        // per path 1 where kept, then prefix sums
layout(std430, binding = 5) buffer Entries { uint entries[]; };  // per path, then prefix sums
#define PATHS_BINDING 6
#define POINTS_BINDING 7
#define POINTS_ACCESS  // written here
#include "strokes/window_paths.glsl"
#include "util/rows.glsl"

dvec2 window_of(uint q) { return dvec2(points[q].x, points[q].y); }
double depth_of(uint q) { return points[q].depth; }
dvec3 world_of(uint q) { return worlds[q].xyz; }
uvec2 faces_of(uint q) { return uvec2(0u); }  // a silhouette's samples test their own key alone
double pressure_of(uint q) { return 1.0lf; }

#include "strokes/path_rows.glsl"

uniform float near;                    // the camera's near plane
uniform float width, height, step_px;  // the window and strokes.vis_step_px, exact as doubles
uniform uint first_point;              // where these paths' points start in the table

vec4 path_row(uint p) { return texelFetch(path_table, table_texel(1u + p), 0); }

#if defined(STEP_ARGS)
void main() { silhouette_args = row_groups(uint(texelFetch(path_table, table_texel(0u), 0).x)); }
#elif defined(STEP_PIECES)
void main() {
  uint p = row_index();
  if (p >= silhouette_args.w) return;
  vec4 row = path_row(p);
  uint first = uint(row.y), n = uint(row.z), flags = uint(row.w);
  // PathBuilder::add: a silhouette keeps its first piece of two points or more in front of
  // the near plane; it is closed where no point is behind it.
  uint start = first, count = 0u;
  bool whole = true;
  for (uint q = first; q < first + n; ++q) {
    if (depth_of(q) >= double(near)) {
      ++count;
      continue;
    }
    whole = false;
    if (count >= 2u) break;
    start = q + 1u, count = 0u;
  }
  if (count < 2u) {
    pieces[p] = uvec4(start, 0u, 0u, 0u), kept[p] = 0u, entries[p] = 0u;
    return;
  }
  bool closed = (flags & 1u) != 0u && whole;
  pieces[p] = uvec4(start, count, closed ? 1u : 0u, (flags & 2u) != 0u ? 1u : 0u);
  kept[p] = 1u;
  entries[p] = (closed ? count : count - 1u) + 1u;
  add_bounds(2u, start, count, closed, dvec2(double(width), double(height)), double(step_px));
}
#elif defined(STEP_ROWS)
void main() {
  uint p = row_index();
  if (p >= silhouette_args.w || pieces[p].y == 0u) return;
  uvec4 piece = pieces[p];
  bool closed = piece.z != 0u;
  double length = write_points(piece.x, piece.y, closed, first_point);
  // common/strokes/visibility.cpp sample_at: a silhouette's byte window (bit 8: closed).
  uint byte_window = uint(min(255.0lf, ceil(2.0lf * max(2.0lf, 256.0lf / max(length, 1e-9lf)))));
  Path row;
  row.first_point = first_point + piece.x, row.points = piece.y;
  row.first_entry = crease_entries + entries[p];
  row.kind = 1u | (closed ? kPathClosed : 0u) | (piece.w != 0u ? kPathInIds : 0u);  // kSilhouetteSample
  row.key = uint(path_row(p).x) - 1u + silhouette_base;
  row.byte_window = byte_window | (closed ? 0x100u : 0u);
  row.sampled = 0u, row.style = 2u;  // window_paths.hpp PathTable::style_of
  row.length_px = length, row.alpha_scale = 1.0lf, row.width_scale = 1.0lf;
  paths[crease_rows + kept[p]] = row;
}
#elif defined(STEP_TOTALS)
void main() {
  silhouette_rows = kept[silhouette_args.w];
  silhouette_entries = entries[silhouette_args.w];
}
#endif
