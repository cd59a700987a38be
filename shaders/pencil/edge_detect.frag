#version 450 core
// Edge detection (Nienhaus & Döllner 2003, as given in Pacheco §2): contour darkness d = 1 - I_n I_z
// (common_edge.glsl). Also contour lighting (Lee Eq. 1) in the same pass:
// d' = d (1 - lambda min(1, sum intensity max(0, N.L))), N the shading normal.
// A frame keeps only d'; d is a second output for a dump and the parity runs.
#include "scene/common_lights.glsl"
#include "pencil/common_edge.glsl"

uniform sampler2D shading_normals;  // for the lighting

layout(location = 0) out float lit_contour_darkness;
#if WRITE_UNLIT
layout(location = 1) out float contour_darkness;
#endif
#if MARK_CONTOUR_BLOCKS
// The CONTOUR_BLOCK x CONTOUR_BLOCK blocks of pixels with some d' > 0, for multiple contour
// drawing (gpu/pencil/multi_contour.hpp): cleared before the pass, and every pixel that marks one
// stores the same 1.
layout(r32f, binding = 0) uniform writeonly image2D contour_block_marks;
#endif

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  float d = contour_darkness_at(x);
  float l_c = 1.0 - contour_light.light_influence * min(1.0, light_sum(texelFetch(shading_normals, x, 0).xyz));
  lit_contour_darkness = d * l_c;
#if WRITE_UNLIT
  contour_darkness = d;
#endif
#if MARK_CONTOUR_BLOCKS
  if (d * l_c > 0.0) imageStore(contour_block_marks, x / CONTOUR_BLOCK, vec4(1.0));
#endif
}
