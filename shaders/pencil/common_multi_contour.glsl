// Multiple contour drawing (Lee §4.2-4.3) at one pixel, shared by
// multi_contour.frag and compose.frag (which draws the contours itself in a frame):
//   d_k = d'(p + offset_k(p)),  t_k = 1 - T_c(p / texture_scale + o_k)
//   D_c = 1 - prod_k (1 - alpha d_k mix(1, t_k, texture_strength))
uniform sampler2D lit_contour_darkness;  // LINEAR, CLAMP_TO_EDGE
uniform sampler2DArray copy_inputs;      // per copy: offset_k(p), mix(1, t_k, texture_strength) (contour_copies.frag)
uniform sampler2D block_reach_max;       // 1 where a marked block is within reach (contour_block_reach.frag)

// Whether every d_k is 0 at pixel x, so that D_c = 0: its block is beyond the copies'
// reach of any d' > 0 (gpu/pencil/multi_contour.cpp).
bool no_copy_reaches(ivec2 x) { return texelFetch(block_reach_max, x / CONTOUR_BLOCK, 0).r == 0.0; }

// D_c from the first `copies` copies (0: none, D_c = 0) at pixel center p.
float multi_contour_darkness(vec2 p, int copies) {
  vec2 window = vec2(textureSize(lit_contour_darkness, 0));
  float untouched = 1.0;
  for (int k = 0; k < copies; ++k) {
    vec3 copy = texelFetch(copy_inputs, ivec3(p, k), 0).xyz;
    float d_k = texture(lit_contour_darkness, (p + copy.xy) / window).r;
    untouched *= 1.0 - contour.stroke_opacity * d_k * copy.z;
  }
  return 1.0 - untouched;
}
