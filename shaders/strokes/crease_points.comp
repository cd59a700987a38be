#version 450 core
// Crease and border points (Kalnins et al. 2002, §4.5), one invocation per path point: its window
// position and depth, and the keys of the first two faces around its segment that face the
// eye (common/strokes/crease_points.hpp), in float. The facing test n·(eye - p0) runs in
// object space, times the sign of the object transform's determinant: the sign of the
// world-space test, which the reference evaluates.
layout(local_size_x = 64) in;

#include "util/common_table.glsl"
#include "util/window_projection.glsl"

layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer Faces { uvec4 faces[]; };
// Per point: its vertex, where its segment's faces start in Around and how many there are.
layout(std430, binding = 2) readonly buffer Records { uvec4 records[]; };
layout(std430, binding = 3) readonly buffer Around { uint around[]; };
layout(rgba32f, binding = 0) writeonly uniform image2D window;
layout(rg32f, binding = 1) writeonly uniform image2D front_faces;

uniform vec3 eye;            // object space
uniform float handedness;    // the sign of the object transform's determinant
uniform uint first_key;      // the object's face 0's key
uniform uint first_record;   // of this dispatch's object
uniform uint record_count;   // of this object
uniform uint first_point;    // of this dispatch (dispatch_in_chunks)

bool faces_eye(uint f) {
  uvec4 t = faces[f];
  vec3 p0 = positions[t.x].xyz, p1 = positions[t.y].xyz, p2 = positions[t.z].xyz;
  return handedness * dot(cross(p1 - p0, p2 - p0), eye - p0) > 0.0;
}

void main() {
  uint i = first_point + gl_GlobalInvocationID.x;
  if (i >= record_count) return;
  uvec4 r = records[first_record + i];
  ivec2 texel = table_texel(first_record + i);
  imageStore(window, texel, vec4(project(positions[r.x].xyz), 0.0));
  vec2 keys = vec2(0.0);
  int found = 0;
  for (uint k = 0u; k < r.z && found < 2; ++k)
    if (faces_eye(around[r.y + k])) keys[found++] = float(first_key + around[r.y + k]);
  imageStore(front_faces, texel, vec4(keys, 0.0, 0.0));
}
