#version 450 core
// Sketchy drawing's maps (Nienhaus & Döllner 2004, §3.1), the twin of reference/sketchy/sketchy_maps.cpp: the edge
// map with the depth its darkness belongs to, and the shade map.
#include "pencil/common_edge.glsl"

uniform usampler2D ids;     // object index + 1, 0 = background
uniform sampler2D colors;   // texel k: object k's unlit color

layout(location = 0) out vec2 edge_map;   // darkness, edge depth
layout(location = 1) out vec4 shade_map;  // color, alpha = coverage

// The nearest linear depth among X and its diagonals, the pixels d is made of.
float edge_depth(ivec2 x) {
  float d = normal_and_depth_at(x).w;
  for (int dy = -1; dy <= 1; dy += 2)
    for (int dx = -1; dx <= 1; dx += 2) d = min(d, normal_and_depth_at(x + ivec2(dx, dy)).w);
  return d;
}

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  edge_map = vec2(contour_darkness_at(x), edge_depth(x));
  uint id = texelFetch(ids, x, 0).r;
  shade_map = id == 0u ? vec4(0.0) : vec4(texelFetch(colors, ivec2(int(id) - 1, 0), 0).rgb, 1.0);
}
