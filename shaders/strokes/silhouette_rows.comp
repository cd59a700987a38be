#version 450 core
// The silhouette paths as window paths, on the GPU (Kalnins et al. 2002, §4.5): the rows of the
// frame's path table (strokes/window_paths.glsl) that common/strokes/strokes.cpp window_lines
// makes of them on the CPU, written where the CPU left them room, and the bounds the CPU sizes the
// later steps' buffers by (common/strokes/visibility.hpp first_round_bound, length_in_margin),
// summed. The steps of gpu/strokes/silhouette_rows.cpp:
//   STEP_ARGS:   one invocation: the groups over the paths;
//   STEP_PIECES: per path, the piece it keeps, its entries, and its bounds added to the sums;
//   STEP_ROWS:   per kept path, its row and its points' rows, placed by the prefix sums of
//                which paths are kept and of their entries;
//   STEP_TOTALS: one invocation: the paths kept and their entries, beside the sums.
const uint kPathsGroup = 64u;
#if defined(STEP_ARGS) || defined(STEP_TOTALS)
layout(local_size_x = 1) in;
#else
layout(local_size_x = kPathsGroup) in;
#endif

#include "util/common_table.glsl"

uniform sampler2D path_table;  // silhouette_paths.paths: row 0 (paths, points); 1 + p: (start + 1, first, points, flags)

// The groups over the paths (x, y, 1) and their count; then 64-bit sums (low, high) of the
// paths' first-round samples, most runs, their most length and most points; then the paths
// kept and their entries (gpu/strokes/silhouette_rows.cpp Counts).
layout(std430, binding = 0) buffer Counts {
  uvec4 args;
  uint sums[8];
  uint kept_total, entry_total, pad0, pad1;
};
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

uniform float near;                                  // the camera's near plane
uniform float width, height, step_px;                // the window and strokes.vis_step_px, exact as doubles
uniform uint first_path, first_point, first_entry;  // where these start in the table (after the CPU's points)
uniform uint silhouette_base;                        // common/strokes/strokes.hpp WindowLines

uint path_index() { return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * kPathsGroup + gl_LocalInvocationID.x; }
vec4 path_row(uint p) { return texelFetch(path_table, table_texel(1u + p), 0); }
dvec2 window_of(uint q) { return dvec2(points[q].x, points[q].y); }

#if defined(STEP_ARGS)
const uint kMaxGroups = 65535u;  // per dimension (GL_MAX_COMPUTE_WORK_GROUP_COUNT)

void main() {
  uint count = uint(texelFetch(path_table, table_texel(0u), 0).x);
  uint groups = (count + kPathsGroup - 1u) / kPathsGroup;
  uint rows = (groups + kMaxGroups - 1u) / kMaxGroups;
  args = uvec4(rows == 0u ? 0u : (groups + rows - 1u) / rows, rows, 1u, count);
}
#elif defined(STEP_PIECES)
const double kMargin = 4.0lf;  // common/strokes/visibility.cpp kWindowMargin

// Adds v >= 0 to the 64-bit sum i, carrying where the low word wraps.
void add_to_sum(uint i, double v) {
  double high = floor(v / 4294967296.0lf);
  uint low = uint(v - high * 4294967296.0lf), before = atomicAdd(sums[2u * i], low);
  atomicAdd(sums[2u * i + 1u], uint(high) + (before + low < before ? 1u : 0u));
}

// A point clear of the margin's edges by more than rounding moves it (first_round_bound).
bool clear(dvec2 q) {
  const double inside = kMargin - 1e-3lf;
  return q.x > -inside && q.y > -inside && q.x < double(width) + inside && q.y < double(height) + inside;
}

void main() {
  uint p = path_index();
  if (p >= args.w) return;
  vec4 row = path_row(p);
  uint first = uint(row.y), n = uint(row.z), flags = uint(row.w);
  // PathBuilder::add: the first piece of two points or more in front of the near plane;
  // closed where no point is behind it.
  uint start = first, count = 0u;
  bool whole = true;
  for (uint q = first; q < first + n; ++q) {
    if (points[q].depth >= double(near)) {
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
  uint segment_count = closed ? count : count - 1u;
  entries[p] = segment_count + 1u;
  double bound = 3.0lf, inside = 0.0lf;  // first_round_bound, length_in_margin
  dvec2 size = dvec2(double(width), double(height));
  for (uint k = 0u; k < segment_count; ++k) {
    dvec2 a = window_of(start + k), b = window_of(start + (k + 1u) % count);
    double t0, t1;
    if (!clip_to_window(a, b, size, kMargin, t0, t1)) continue;
    double along = (t1 - t0) * distance(a, b);
    bound += along / double(step_px) + (clear(a) && clear(b) ? 2.0lf : 4.0lf);
    inside += along;
  }
  double runs = floor(bound / 2.0lf) + 1.0lf;  // window_paths.hpp RunTables
  add_to_sum(0u, ceil(bound));
  add_to_sum(1u, runs);
  add_to_sum(2u, ceil(inside + runs));
  add_to_sum(3u, double(count) + 2.0lf * runs);
}
#elif defined(STEP_ROWS)
void main() {
  uint p = path_index();
  if (p >= args.w || pieces[p].y == 0u) return;
  uvec4 piece = pieces[p];
  uint start = piece.x, count = piece.y;
  bool closed = piece.z != 0u;
  // The window arc lengths, as PathBuilder::flush sums them.
  double s = 0.0lf;
  for (uint k = 0u; k < count; ++k) {
    uint q = start + k, next = start + (k + 1u) % count;
    bool segment = closed || k + 1u < count;
    Point row;
    row.window = window_of(q), row.s = s, row.faces = uvec2(0u), row.pressure = 1.0lf;
    row.depth = points[q].depth;
    row.world_step = segment ? distance(worlds[q].xyz, worlds[next].xyz) : 0.0lf;
    row.pad = 0.0lf;
    path_points[first_point + q] = row;
    if (k + 1u < count) s += distance(window_of(q), window_of(next));
  }
  double length = closed ? s + distance(window_of(start + count - 1u), window_of(start)) : s;
  // common/strokes/visibility.cpp sample_at: a silhouette's byte window (bit 8: closed).
  uint byte_window = uint(min(255.0lf, ceil(2.0lf * max(2.0lf, 256.0lf / max(length, 1e-9lf)))));
  Path row;
  row.first_point = first_point + start, row.points = count, row.first_entry = first_entry + entries[p];
  row.kind = 1u | (closed ? kPathClosed : 0u) | (piece.w != 0u ? kPathInIds : 0u);  // kSilhouetteSample
  row.key = uint(path_row(p).x) - 1u + silhouette_base;
  row.byte_window = byte_window | (closed ? 0x100u : 0u);
  row.sampled = 0u, row.style = 2u;  // window_paths.hpp PathTable::style_of
  row.length_px = length, row.alpha_scale = 1.0lf, row.width_scale = 1.0lf;
  paths[first_path + kept[p]] = row;
}
#elif defined(STEP_TOTALS)
void main() {
  kept_total = kept[args.w];
  entry_total = entries[args.w];
}
#endif
