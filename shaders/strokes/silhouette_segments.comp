#version 450 core
// Silhouette segments (Kalnins et al. 2002, §4.5), one invocation per face: the formula of
// common/strokes/feature_lines.cpp (corner_silhouette_values, face_segment, edge_crossing)
// in float.
layout(local_size_x = 64) in;

#include "util/common_table.glsl"
#include "util/window_projection.glsl"

// gpu/strokes/stroke_meshes.hpp: every stroke object's positions; per face record, its
// corners' vertices (its object's numbering), bit k of w: the edge in slot k runs from
// corner k + 1 to corner k.
layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer Faces { uvec4 faces[]; };
layout(std430, binding = 2) readonly buffer Normals { vec4 normals[]; };  // per corner 3 r + k, crease-aware
layout(rgba32f, binding = 0) writeonly uniform image2D ends;
layout(r32f, binding = 1) writeonly uniform image2D facing;
layout(rg32f, binding = 2) writeonly uniform image2D slots;

uniform vec3 eye;         // object space
uniform bool normalized;  // g = n·normalize(eye - x); false: n·(eye - x)
uniform float near;
uniform uint face_count, first_face, first_record, first_vertex;  // first_face: of this dispatch

const float kZeroG = -1e-8;  // g = 0 exactly is taken as -1e-8

float silhouette_test(vec3 n, vec3 x) {
  vec3 to_eye = eye - x;
  if (normalized) {
    float len = length(to_eye);
    to_eye = len > 0.0 && !isinf(len) ? to_eye / len : vec3(0.0);
  }
  float g = dot(n, to_eye);
  return g == 0.0 || isnan(g) || isinf(g) ? kZeroG : g;
}

// The crossing in slot k, p = a + (b - a) g_a / (g_a - g_b), a -> b the edge's own way.
vec3 edge_crossing(vec3 c[3], float g[3], uint reversed, int k) {
  int ka = k, kb = (k + 1) % 3;
  if ((reversed & (1u << k)) != 0u) {
    ka = kb;
    kb = k;
  }
  return c[ka] + (c[kb] - c[ka]) * (g[ka] / (g[ka] - g[kb]));
}

// Face f's rows: every face's are written each frame, 0 where it holds no segment.
void put(uint f, vec4 window_ends, float front, vec2 slot_pair) {
  ivec2 texel = table_texel(first_record + f);
  imageStore(ends, texel, window_ends);
  imageStore(facing, texel, vec4(front));
  imageStore(slots, texel, vec4(slot_pair, 0.0, 0.0));
}

void main() {
  uint f = first_face + gl_GlobalInvocationID.x;
  if (f >= face_count) return;
  put(f, vec4(0.0), 0.0, vec2(0.0));
  uint record = first_record + f;
  uvec4 face = faces[record];
  vec3 c[3];
  float g[3];
  for (int k = 0; k < 3; ++k) {
    c[k] = positions[first_vertex + face[k]].xyz;
    g[k] = silhouette_test(normals[3u * record + uint(k)].xyz, c[k]);
  }
  int found_slots[2];
  int found = 0;
  for (int k = 0; k < 3 && found < 2; ++k)
    if ((g[k] > 0.0) != (g[(k + 1) % 3] > 0.0)) found_slots[found++] = k;
  if (found < 2) return;
  // Run with g > 0 on the left: from the slot after the lone corner to the one before it
  // when its g > 0 (common/strokes/feature_lines.hpp oriented_slots).
  int lone = found_slots[1] == found_slots[0] + 1 ? found_slots[1] : 0, before = (lone + 2) % 3;
  int entry = g[lone] > 0.0 ? lone : before, exit = g[lone] > 0.0 ? before : lone;
  vec3 a = edge_crossing(c, g, face.w, entry), b = edge_crossing(c, g, face.w, exit);
  // Front-facing when the in-face gradient of g, Σ g_i (N × e_i), points towards the eye.
  vec3 n = cross(c[1] - c[0], c[2] - c[0]), gradient = vec3(0.0);
  for (int i = 0; i < 3; ++i) gradient += g[i] * cross(n, c[(i + 2) % 3] - c[(i + 1) % 3]);
  bool front = dot(gradient, eye - 0.5 * (a + b)) >= 0.0;
  vec3 wa = project(a), wb = project(b);
  if (wa.z < near || wb.z < near) return;
  put(f, vec4(wa.xy, wb.xy), front ? 1.0 : -1.0, vec2(entry, exit));
}
