#version 450 core
// Edge detection (SPEC 2.2): contour darkness d = 1 - I_n I_z (common_edge.glsl).
// Also contour lighting (SPEC 2.3, Lee Eq. 1) in the same pass, as a second output:
// d' = d (1 - lambda min(1, sum intensity max(0, N.L))), N the shading normal.
#include "common_lights.glsl"
#include "common_edge.glsl"

uniform sampler2D shading_normals;  // for the lighting

layout(location = 0) out float contour_darkness;
layout(location = 1) out float lit_contour_darkness;

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  contour_darkness = contour_darkness_at(x);
  float l_c = 1.0 - contour.light_influence * min(1.0, light_sum(texelFetch(shading_normals, x, 0).xyz));
  lit_contour_darkness = contour_darkness * l_c;
}
