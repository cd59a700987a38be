#version 450 core
// Crease and border paths as window paths, on the GPU (Kalnins et al. 2002, §4.5): the rows of
// the frame's path table (strokes/window_paths.glsl) that common/strokes/strokes.cpp
// window_lines makes of them on the CPU (PathBuilder::add, flush), in double, from their
// points and the faces around their segments, uploaded once (common/strokes/crease_points.hpp
// crease_records); and their bounds, summed (strokes/path_rows.glsl). The steps of
// gpu/strokes/crease_rows.cpp (STEP_POINTS; the others: gpu/strokes/piece_rows.hpp):
//   STEP_POINTS: per point, its world and window positions and view depth, and the keys of
//                the first two faces around its segment that face the eye (faces_eye);
//   STEP_PIECES: per path, its pieces in front of the near plane, each of two points or
//                more, their entries, and their bounds;
//   STEP_ROWS:   per path, its pieces' rows and their points' rows, placed by the prefix
//                sums of the pieces and of their entries;
//   STEP_TOTALS: one invocation: the pieces and their entries, and the silhouettes' first key.
#if defined(STEP_TOTALS)
layout(local_size_x = 1) in;
#else
layout(local_size_x = 64) in;  // kRowsGroup
#endif
#if defined(STEP_ROWS)
#define ROWS
#endif

struct CreasePoint {  // gpu/strokes/crease_rows.cpp ScratchPoint
  dvec4 world;
  dvec2 window;
  double depth, pad;
  uvec2 faces;  // keys of the first two faces around the segment to the next point that face the eye
  uvec2 pad2;
};

#if defined(STEP_POINTS)
// Per point: its vertex, where its segment's faces start in Around, how many, its object.
layout(std430, binding = 0) readonly buffer Records { uvec4 records[]; };
layout(std430, binding = 1) readonly buffer Around { uint around[]; };  // the object's own face numbers
layout(std430, binding = 2) readonly buffer Positions { vec4 positions[]; };  // every object's, in order
layout(std430, binding = 3) readonly buffer Faces { uvec4 faces[]; };  // per face record: its corners
struct Object {  // gpu/strokes/crease_rows.cpp ObjectRow
  dmat4 model;
  uint first_record, first_vertex, pad0, pad1;
};
layout(std430, binding = 4) readonly buffer Objects { Object objects[]; };
layout(std430, binding = 5) writeonly buffer Scratch { CreasePoint scratch[]; };
layout(std430, binding = 6) readonly buffer Frame {
  dmat4 clip, view;  // world to clip, to view
  dvec4 eye;         // world space
};
uniform float width, height;
uniform uint record_count, first;  // first: of this dispatch (dispatch_in_chunks)

dvec3 world_corner(Object o, uint record, int k) {
  return (o.model * dvec4(dvec3(positions[o.first_vertex + faces[record][k]].xyz), 1.0lf)).xyz;
}

// common/strokes/strokes.cpp faces_eye, in world space.
bool faces_eye(Object o, uint face) {
  uint record = o.first_record + face;
  dvec3 p0 = world_corner(o, record, 0), p1 = world_corner(o, record, 1), p2 = world_corner(o, record, 2);
  return dot(cross(p1 - p0, p2 - p0), eye.xyz - p0) > 0.0lf;
}

void main() {
  uint i = first + gl_GlobalInvocationID.x;
  if (i >= record_count) return;
  uvec4 r = records[i];
  Object o = objects[r.w];
  dvec4 world = o.model * dvec4(dvec3(positions[o.first_vertex + r.x].xyz), 1.0lf), c = clip * world;
  CreasePoint p;
  p.world = world;
  p.window = (c.xy / c.w * 0.5lf + 0.5lf) * dvec2(double(width), double(height));
  p.depth = -(view * world).z, p.pad = 0.0lf;
  p.faces = uvec2(0u), p.pad2 = uvec2(0u);
  uint found = 0u;
  for (uint k = 0u; k < r.z && found < 2u; ++k)
    if (faces_eye(o, around[r.y + k])) p.faces[found++] = o.first_record + around[r.y + k] + 1u;  // its key
  scratch[i] = p;
}
#else
// Per path: its first point, its points, flags (1: closed, 2: a border).
layout(std430, binding = 1) readonly buffer Defs { uvec4 defs[]; };
layout(std430, binding = 2) readonly buffer Scratch { CreasePoint scratch[]; };
layout(std430, binding = 3) buffer Pieces { uint pieces[]; };    // per path its pieces, then prefix sums
layout(std430, binding = 4) buffer Entries { uint entries[]; };  // per path its pieces' entries, then prefix sums
#define PATHS_BINDING 6
#define POINTS_BINDING 7
#define POINTS_ACCESS  // written here
#include "strokes/window_paths.glsl"
#include "util/rows.glsl"

dvec2 window_of(uint q) { return scratch[q].window; }
double depth_of(uint q) { return scratch[q].depth; }
dvec3 world_of(uint q) { return scratch[q].world.xyz; }
uvec2 faces_of(uint q) { return scratch[q].faces; }
double pressure_of(uint q) { return 1.0lf; }

#include "strokes/path_rows.glsl"

uniform float near, width, height, step_px;  // exact as doubles
uniform uint source_count, face_count;  // the creases and borders (defs), the faces keyed before them
uniform uint first_point;  // where the points start in the table

#if defined(STEP_PIECES) || defined(STEP_ROWS)
void main() {
  uint p = row_index();
  if (p >= source_count) return;
  uvec4 d = defs[p];
  uint style = (d.w & 2u) != 0u ? 1u : 0u;  // window_paths.hpp PathTable::style_of
  uint count = 0u, start = d.x, made = 0u, made_entries = 0u;
  bool whole = true;
  // PathBuilder::add: every piece of two points or more in front of the near plane; the last
  // is closed where the path is and no point is behind it.
  for (uint q = d.x; q <= d.x + d.y; ++q) {
    bool at_end = q == d.x + d.y;
    if (!at_end && depth_of(q) >= double(near)) {
      ++count;
      continue;
    }
    whole = whole && at_end;
    if (count >= 2u) {
      bool closed = at_end && whole && (d.w & 1u) != 0u;
#if defined(STEP_PIECES)
      add_bounds(style, start, count, closed, dvec2(double(width), double(height)), double(step_px));
#else
      Path row;
      row.first_point = first_point + start, row.points = count;
      row.first_entry = entries[p] + made_entries;
      row.kind = 0u | (closed ? kPathClosed : 0u) | kPathInIds;  // kCreaseSample, drawn in the ID image
      row.key = face_count + 1u + pieces[p] + made;  // common/strokes/strokes.cpp assign_keys
      row.byte_window = 0u, row.sampled = 0u, row.style = style;
      row.length_px = write_points(start, count, closed, first_point);
      row.alpha_scale = 1.0lf, row.width_scale = 1.0lf;
      paths[pieces[p] + made] = row;
#endif
      made += 1u, made_entries += (closed ? count : count - 1u) + 1u;
    }
    start = q + 1u, count = 0u;
  }
#if defined(STEP_PIECES)
  pieces[p] = made, entries[p] = made_entries;
#endif
}
#elif defined(STEP_TOTALS)
void main() {
  crease_rows = pieces[source_count];
  crease_entries = entries[source_count];
  silhouette_base = ((face_count + crease_rows) >> 8) + 1u;  // common/strokes/strokes.cpp assign_keys
}
#endif
#endif
