#version 450 core
// Contour lighting (SPEC 2.3, Lee Eq. 1): d' = d (1 - lambda min(1, sum I max(0, N.L))).
#include "common_lights.glsl"

uniform sampler2D contour_darkness;
uniform sampler2D normals;

layout(location = 0) out float lit_contour_darkness;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float l_c = 1.0 - contour.light_influence * min(1.0, light_sum(texelFetch(normals, p, 0).xyz));
  lit_contour_darkness = texelFetch(contour_darkness, p, 0).r * l_c;
}
