#version 450 core
// Edge detection (SPEC 2.2): contour darkness d = 1 - I_n I_z.
// Neighbors A B C / D X E / F G H, y up (window coordinates), clamp-to-edge.
// Also contour lighting (SPEC 2.3, Lee Eq. 1) in the same pass, as a second output:
// d' = d (1 - lambda min(1, sum intensity max(0, N.L))), N the shading normal.
#include "common_lights.glsl"

uniform sampler2D normals;          // view-space normals (shading or face, chosen on the CPU)
uniform sampler2D depth;            // linear view depth
uniform sampler2D shading_normals;  // for the lighting
uniform float near_plane;
uniform float far_plane;

layout(location = 0) out float contour_darkness;
layout(location = 1) out float lit_contour_darkness;

ivec2 clamped(ivec2 p) { return clamp(p, ivec2(0), textureSize(depth, 0) - 1); }
vec3 normal_at(ivec2 p) { return texelFetch(normals, clamped(p), 0).xyz; }
float normalized_depth_at(ivec2 p) { return (texelFetch(depth, clamped(p), 0).r - near_plane) / (far_plane - near_plane); }

// N_1.N_2; two background pixels (zero normals) count as continuous unless the
// literal formula is asked for (common/edge_detect.hpp).
float normal_agreement(vec3 n1, vec3 n2) {
  bool both_background = dot(n1, n1) == 0.0 && dot(n2, n2) == 0.0;
  return both_background && edge.background_pairs == EDGE_BACKGROUND_PAIRS_CONTINUOUS ? 1.0 : dot(n1, n2);
}

float depth_factor(float z1, float z2) {
  float f = 1.0 - min(1.0, 0.5 * edge.depth_scale * abs(z1 - z2));
  return f * f;
}

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  ivec2 a = x + ivec2(-1, 1), h = x + ivec2(1, -1), c = x + ivec2(1, 1), f = x + ivec2(-1, -1);
  float i_n = clamp(0.5 * (normal_agreement(normal_at(a), normal_at(h)) + normal_agreement(normal_at(c), normal_at(f))), 0.0, 1.0);
  float i_z = depth_factor(normalized_depth_at(a), normalized_depth_at(h)) *
              depth_factor(normalized_depth_at(c), normalized_depth_at(f));
  contour_darkness = 1.0 - i_n * i_z;
  float l_c = 1.0 - contour.light_influence * min(1.0, light_sum(texelFetch(shading_normals, x, 0).xyz));
  lit_contour_darkness = contour_darkness * l_c;
}
