#version 450 core
// Composition and enhancement (Lee Eq. 6). With MULTI_CONTOUR on, this pass
// draws the contours itself (Lee et al. 2006, §4.2-4.3, common_multi_contour.glsl) instead of reading D_c:
// a frame then writes and reads no D_c target (gpu/pencil/compose.hpp).
uniform sampler2D interior_darkness;
uniform sampler2D paper_color;  // read texel for pixel, wrapping
uniform bool has_contours;
uniform bool has_interior;
uniform bool has_paper;
#include "util/common_wrap.glsl"
#if MULTI_CONTOUR
#include "pencil/common_multi_contour.glsl"
#if WRITE_CONTOUR_DARKNESS
layout(location = 1) out float multi_contour_darkness_out;  // D_c, for a dump
#endif
float contour_darkness_at(ivec2 x) {
  // No loop at all, rather than an if around it, where no copy reaches: llvmpipe leaves a
  // loop once no pixel of a block runs it, but runs both sides of an if.
  float d_c = multi_contour_darkness(vec2(x) + 0.5, no_copy_reaches(x) ? 0 : contour.copies);
#if WRITE_CONTOUR_DARKNESS
  multi_contour_darkness_out = d_c;
#endif
  return d_c;
}
#else
uniform sampler2D contour_darkness;
float contour_darkness_at(ivec2 x) { return texelFetch(contour_darkness, x, 0).r; }
#endif

layout(location = 0) out vec4 color;

// I = (1 - D_c)(1 - D_i'), D_i' = D_i (1 - a D_c)
float composed_intensity(float d_c, float d_i) {
  float attenuated = d_i * (1.0 - compose.contour_attenuation * d_c);
  return (1.0 - d_c) * (1.0 - attenuated);
}

// I'' = mix(I, smoothstep(0, 1, I), contrast)
float enhanced(float i) { return i + (smoothstep(0.0, 1.0, i) - i) * compose.contrast; }

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  float d_c = has_contours ? contour_darkness_at(x) : 0.0;
  float d_i = has_interior ? texelFetch(interior_darkness, x, 0).r : 0.0;
  vec3 c_p = has_paper ? texelFetch(paper_color, wrapped_texel(x, textureSize(paper_color, 0)), 0).rgb : vec3(1.0);
  color = vec4(enhanced(composed_intensity(d_c, d_i)) * c_p, 1.0);
}
