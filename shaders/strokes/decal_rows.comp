#version 450 core
// Decals and hatches as window paths, on the GPU (Kalnins et al. 2002, §3, §6): the rows of the
// frame's path table (strokes/window_paths.glsl) that common/strokes/strokes.cpp window_lines
// makes of them on the CPU (PathBuilder::add_decal, flush), in double, written after the
// silhouettes' (silhouette_rows.comp), from their points in object space (uploaded once; a
// mobile hatch's copies moved here, along their chart's u-line, common/strokes/mobile_hatching.hpp);
// and their bounds, summed per decal (strokes/path_rows.glsl).
// The steps of gpu/strokes/decal_rows.cpp (STEP_POINTS; the others: gpu/strokes/piece_rows.hpp):
//   STEP_POINTS: per surface stroke drawn this frame, its points (a copy's moved) placed in the
//                world and the window, where they lie on the surface (and on its hatch's object);
//   STEP_PIECES: per stroke, its pieces (split where a point missed, where the object
//                changes and at the near plane), each of two points or more, their
//                entries, and their bounds;
//   STEP_ROWS:   per stroke, its pieces' rows and their points' rows, placed by the prefix
//                sums of the pieces and of their entries;
//   STEP_TOTALS: one invocation: the pieces and their entries.
#if defined(STEP_TOTALS)
layout(local_size_x = 1) in;
#else
layout(local_size_x = 64) in;  // kRowsGroup
#endif
#if defined(STEP_ROWS)
#define ROWS
#endif

const uint kMissed = 0xffffffffu;  // common/strokes/decal.hpp: the point lies on no object

struct Stroke {  // gpu/strokes/decal_rows.cpp StrokeRow
  uint first_record, count, first_point, style;
  uint object;  // its hatch's group's object, else kMissed
  uint flags;   // 1: a mobile hatch's copy; 2: a hatch
  uint chart;   // a copy's: its group's chart (Charts)
  uint pad0;
  double alpha, width;  // its weight this frame (common/strokes/hatching.hpp HatchWeight)
  double copy_u, copy_scale, c_u;  // a copy's: u at its maximum, its scale in u, its group's c.u
};
struct DecalPoint {  // gpu/strokes/decal_rows.cpp ScratchPoint
  dvec4 world;
  dvec2 window;
  double depth, pressure;
  uint object;  // kMissed where it missed or lies off its hatch's object
  uint key;     // its face's (common/strokes/strokes.hpp WindowLines::face_key)
  uint pad0, pad1;
};
layout(std430, binding = 1) readonly buffer Strokes { Stroke strokes[]; };
layout(std430, binding = 2) buffer Scratch { DecalPoint scratch[]; };

uniform uint source_count;  // the strokes drawn
uniform float near, width, height, step_px;  // exact as doubles
uniform uint first_point;                     // where the points start in the table

#if defined(STEP_POINTS)
struct Record {  // gpu/strokes/decal_rows.cpp RecordRow
  dvec4 local;   // object space (common/strokes/decal.hpp decal_point_local), w: its pressure
  uvec4 at;      // its object (kMissed: none), its face
  dvec2 uv;      // a mobile hatch's point on its group's object: its (u, v) in the group's chart
};
layout(std430, binding = 5) readonly buffer Fixed { Record records[]; };  // the strokes', once
#include "strokes/uv_chart.glsl"
struct Object {  // gpu/strokes/decal_rows.cpp ObjectRow
  dmat4 model;
  uint first_key, pad0, pad1, pad2;  // its first face's key less one
};
layout(std430, binding = 7) readonly buffer Objects {
  dmat4 clip, view;  // world to clip, to view
  Object objects[];
};
#include "util/rows.glsl"

// PathBuilder::add_decal: a point in the world and the window, where it lies on the surface
// (on `object` where that is not kMissed).
DecalPoint placed(Record r, uint object) {
  DecalPoint p;
  p.object = r.at.x == object || object == kMissed ? r.at.x : kMissed;
  p.pressure = r.local.w, p.key = 0u, p.pad0 = 0u, p.pad1 = 0u;
  p.world = dvec4(0.0lf), p.window = dvec2(0.0lf), p.depth = 0.0lf;
  if (p.object == kMissed) return p;
  Object o = objects[p.object];
  dvec4 world = o.model * dvec4(r.local.xyz, 1.0lf), c = clip * world;
  p.world = world;
  p.window = (c.xy / c.w * 0.5lf + 0.5lf) * dvec2(double(width), double(height));
  p.depth = -(view * world).z;
  p.key = o.first_key + r.at.y + 1u;
  return p;
}

// common/strokes/mobile_hatching.cpp MobileHatching::copies: record r of the hatch that copy
// `st` moves, moved along its chart's u-line (MobileHatching::moved) and put back on the
// surface where it lands on a face; missed elsewhere, and where it lay off the group's object.
Record moved(Record r, Stroke st) {
  Chart chart = charts[st.chart];
  precise double u = st.copy_u + st.copy_scale * (r.uv.x - st.c_u);  // rounded as the CPU rounds it: unfused
  UvHit hit;
  if (r.at.x != chart.object || !locate(chart, dvec2(u, r.uv.y), hit)) {
    r.at.x = kMissed;
    return r;
  }
  r.at.y = hit.face;
  r.local.xyz = position(chart, hit);
  return r;
}

void main() {
  uint s = row_index();
  if (s >= source_count) return;
  Stroke st = strokes[s];
  for (uint k = 0u; k < st.count; ++k) {
    uint r = st.first_record + k;
    scratch[st.first_point + k] = placed((st.flags & 1u) != 0u ? moved(records[r], st) : records[r], st.object);
  }
}
#else
layout(std430, binding = 3) buffer Pieces { uint pieces[]; };    // per stroke its pieces, then prefix sums
layout(std430, binding = 4) buffer Entries { uint entries[]; };  // per stroke its pieces' entries, then prefix sums
#define PATHS_BINDING 6
#define POINTS_BINDING 7
#define POINTS_ACCESS  // written here
#include "strokes/window_paths.glsl"
#include "util/rows.glsl"

dvec2 window_of(uint q) { return scratch[q].window; }
double depth_of(uint q) { return scratch[q].depth; }
dvec3 world_of(uint q) { return scratch[q].world.xyz; }
uvec2 faces_of(uint q) { return uvec2(scratch[q].key, scratch[q + 1u].key); }  // of both ends (flush_decal)
double pressure_of(uint q) { return scratch[q].pressure; }

#include "strokes/path_rows.glsl"

#if defined(STEP_PIECES) || defined(STEP_ROWS)
void main() {
  uint s = row_index();
  if (s >= source_count) return;
  Stroke st = strokes[s];
  // PathBuilder::add_decal: every run of two points or more on one object in front of the
  // near plane.
  uint start = 0u, count = 0u, object = kMissed, made = 0u, made_entries = 0u;
  for (uint k = 0u; k <= st.count; ++k) {
    uint q = st.first_point + k;
    bool kept = k < st.count && scratch[q].object != kMissed && depth_of(q) >= double(near);
    if (kept && count > 0u && scratch[q].object == object) {
      ++count;
      continue;
    }
    if (count >= 2u) {
#if defined(STEP_PIECES)
      add_bounds(st.style, start, count, false, dvec2(double(width), double(height)), double(step_px));
#else
      Path row;
      row.first_point = first_point + start, row.points = count;
      row.first_entry = crease_entries + silhouette_entries + entries[s] + made_entries;
      row.kind = (st.flags & 2u) != 0u ? 3u : 2u;  // kHatchingSample, kDecalSample: open, not in the ID image
      row.key = 0u, row.byte_window = 0u, row.sampled = 0u, row.style = st.style;
      row.length_px = write_points(start, count, false, first_point);
      row.alpha_scale = st.alpha, row.width_scale = st.width;
      paths[crease_rows + silhouette_rows + pieces[s] + made] = row;
#endif
      made += 1u, made_entries += count;  // an open piece's segments, and its end
    }
    count = kept ? 1u : 0u, start = q;
    if (kept) object = scratch[q].object;
  }
#if defined(STEP_PIECES)
  pieces[s] = made, entries[s] = made_entries;
#endif
}
#elif defined(STEP_TOTALS)
void main() {
  decal_rows = pieces[source_count];
  decal_entries = entries[source_count];
}
#endif
#endif
