#version 450 core
// Base coat (Kalnins et al. 2002, §4.2): s interpolated from the triangle's corners with the barycentrics
// looks up the 1D texture: the coat, straight alpha, on the stroke objects only.
// Formula in common/strokes/basecoat.hpp.

uniform usampler2D ids;  // object id, triangle index
uniform sampler2D bary;
uniform sampler2D coat;  // the 1D texture as one row: LINEAR, CLAMP_TO_EDGE
// Per triangle, its corners' s (common/strokes/basecoat.hpp TriangleShades).
layout(std430, binding = 0) readonly buffer Shades { vec4 corner_shades[]; };
layout(std430, binding = 1) readonly buffer FirstTriangle { uint first_triangle[]; };  // per object

layout(location = 0) out vec4 coat_out;

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  uvec2 id = texelFetch(ids, x, 0).xy;
  if (id.x == 0u) {
    coat_out = vec4(0.0);
    return;
  }
  vec4 s = corner_shades[first_triangle[id.x - 1u] + id.y];  // (s0, s1, s2, coated)
  vec3 w = texelFetch(bary, x, 0).xyz;
  coat_out = s.w * texture(coat, vec2(w.x * s.x + w.y * s.y + w.z * s.z, 0.5));
}
