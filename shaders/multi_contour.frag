#version 450 core
// Multiple contour drawing (SPEC 2.4; Lee §4.2-4.3):
//   d_k = d'(p + offset_k(p)),  t_k = 1 - T_c(p / texture_scale + o_k)
//   D_c = 1 - prod_k (1 - alpha d_k mix(1, t_k, texture_strength))
uniform sampler2D lit_contour_darkness;  // LINEAR, CLAMP_TO_EDGE
uniform sampler2DArray copy_inputs;      // per copy: offset_k(p), mix(1, t_k, texture_strength) (contour_copies.frag)
uniform sampler2D block_reach_max;       // contour_block_reach.frag

layout(location = 0) out float contour_darkness;

void main() {
  vec2 p = gl_FragCoord.xy;  // pixel center
  // Every d_k = 0 here, so D_c = 0, what the target was cleared to (gpu/multi_contour.cpp).
  // A discard, unlike a return, lets llvmpipe skip a block of pixels that all take it.
  if (texelFetch(block_reach_max, ivec2(p) / CONTOUR_BLOCK, 0).r == 0.0) discard;
  vec2 window = vec2(textureSize(lit_contour_darkness, 0));
  float untouched = 1.0;
  for (int k = 0; k < contour.copies; ++k) {
    vec3 copy = texelFetch(copy_inputs, ivec3(gl_FragCoord.xy, k), 0).xyz;
    float d_k = texture(lit_contour_darkness, (p + copy.xy) / window).r;
    untouched *= 1.0 - contour.stroke_opacity * d_k * copy.z;
  }
  contour_darkness = 1.0 - untouched;
}
