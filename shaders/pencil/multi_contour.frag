#version 450 core
// Multiple contour drawing (Lee et al. 2006, §4.2-4.3), common_multi_contour.glsl, as a stage of its own:
// D_c into a float target (a frame fuses it into compose.frag instead).
#include "pencil/common_multi_contour.glsl"

layout(location = 0) out float contour_darkness;

void main() {
  // D_c = 0 here, what the target was cleared to (gpu/pencil/multi_contour.cpp). A discard,
  // unlike a return, lets llvmpipe skip a block of pixels that all take it.
  if (no_copy_reaches(ivec2(gl_FragCoord.xy))) discard;
  contour_darkness = multi_contour_darkness(gl_FragCoord.xy, contour.copies);
}
