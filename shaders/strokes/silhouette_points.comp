#version 450 core
// Silhouette path points in double (Kalnins et al. 2002, §4.5): each point the silhouette
// paths list (common/strokes/silhouette_paths.hpp) placed where g = 0 on its face's slot and
// projected to the window, the steps of gpu/strokes/silhouette_points.cpp. The formula is the
// reference's (common/strokes/feature_lines.cpp silhouette_test, edge_crossing), in double;
// the projection that of common/strokes/strokes.hpp WindowProjection.
//   STEP_ARGS:   one invocation: the groups of STEP_POINTS from the paths' point count;
//   STEP_POINTS: per point, its crossing, its world and window positions.
const uint kPointsGroup = 64u;  // STEP_POINTS' workgroup
#if defined(STEP_ARGS)
layout(local_size_x = 1) in;
#else
layout(local_size_x = kPointsGroup) in;
#endif

#include "util/common_table.glsl"

uniform sampler2D paths;      // silhouette_paths.paths: row 0 (paths, points)
uniform sampler2D crossings;  // silhouette_paths.crossings: (record + 1, slot) per point

layout(std430, binding = 0) buffer Args { uvec4 args; };  // STEP_POINTS' groups (x, y, 1)

#if defined(STEP_ARGS)
const uint kMaxGroups = 65535u;  // per dimension (GL_MAX_COMPUTE_WORK_GROUP_COUNT)

void main() {
  uint points = uint(texelFetch(paths, table_texel(0u), 0).y);
  uint groups = (points + kPointsGroup - 1u) / kPointsGroup;
  uint rows = (groups + kMaxGroups - 1u) / kMaxGroups;
  args = uvec4(rows == 0u ? 0u : (groups + rows - 1u) / rows, rows, 1u, points);
}
#elif defined(STEP_POINTS)

struct Object {  // gpu/strokes/silhouette_points.cpp ObjectRow
  dmat4 model;
  dvec4 eye;  // object space
  uint first_record, first_vertex, lines, pad;
};

struct Point {  // common/strokes/silhouette_paths.hpp SilhouettePoint
  double x, y, depth, t;
  uint record, slot;
};

layout(std430, binding = 1) readonly buffer Objects { Object objects[]; };
layout(std430, binding = 2) readonly buffer Positions { vec4 positions[]; };  // every object's, in order
// Per face record: its corners' vertices (object's own numbering); bit k of w: the edge in
// slot k runs from corner k + 1 to corner k.
layout(std430, binding = 3) readonly buffer Faces { uvec4 faces[]; };
layout(std430, binding = 4) readonly buffer Normals { double normals[]; };  // per record, 3 corners x 3
layout(std430, binding = 5) writeonly buffer Points { Point points[]; };
layout(std430, binding = 6) readonly buffer Frame { dmat4 clip, view; };  // world to clip, to view
layout(std430, binding = 7) writeonly buffer Worlds { dvec4 worlds[]; };  // per point (silhouette_rows.comp)

uniform bool normalized;  // g = n·normalize(eye - x); false: n·(eye - x)
uniform uint object_count;
uniform float width, height;  // widened to double below

const double kZeroG = -1e-8LF;  // g = 0 exactly is taken as -1e-8

// The object whose records hold `record`: the last with first_record <= record.
uint object_of(uint record) {
  uint lo = 0u, hi = object_count;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (objects[mid].first_record <= record) lo = mid;
    else hi = mid;
  }
  return lo;
}

dvec3 corner(Object o, uint record, int k) { return dvec3(positions[o.first_vertex + faces[record][k]].xyz); }

double silhouette_test(Object o, uint record, int k) {
  uint n = 9u * record + 3u * uint(k);
  dvec3 normal = dvec3(normals[n], normals[n + 1u], normals[n + 2u]);
  dvec3 to_eye = o.eye.xyz - corner(o, record, k);
  if (normalized) {
    double len = length(to_eye);
    to_eye = len > 0.0LF && !isinf(len) ? to_eye / len : dvec3(0.0LF);
  }
  double g = dot(normal, to_eye);
  return g == 0.0LF || isnan(g) || isinf(g) ? kZeroG : g;
}

void main() {
  uint q = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * kPointsGroup + gl_LocalInvocationID.x;
  if (q >= args.w) return;
  vec2 crossing = texelFetch(crossings, table_texel(q), 0).xy;
  uint record = uint(crossing.x) - 1u, slot = uint(crossing.y);
  Object o = objects[object_of(record)];
  // The slot's corners the edge's own way (from -> to), so both faces give the same point.
  int ka = int(slot), kb = (ka + 1) % 3;
  if ((faces[record].w & (1u << slot)) != 0u) {
    ka = kb;
    kb = int(slot);
  }
  double ga = silhouette_test(o, record, ka), gb = silhouette_test(o, record, kb), t = ga / (ga - gb);
  // A float chain may name a slot whose signs agree in double: the nearer end, or its middle.
  t = isnan(t) || isinf(t) ? 0.5LF : clamp(t, 0.0LF, 1.0LF);
  dvec3 a = corner(o, record, ka), b = corner(o, record, kb);
  dvec4 world = o.model * dvec4(a + (b - a) * t, 1.0LF), c = clip * world;
  dvec2 window = (c.xy / c.w * 0.5LF + 0.5LF) * dvec2(double(width), double(height));
  points[q] = Point(window.x, window.y, -(view * world).z, t, record, slot);
  worlds[q] = world;
}
#endif
