#version 450 core
// Multiple contour drawing (SPEC 2.4; Lee §4.2-4.3):
//   d_k = d'(p + offset_k(p)),  t_k = 1 - T_c(p / texture_scale + o_k)
//   D_c = 1 - prod_k (1 - alpha d_k mix(1, t_k, texture_strength))
uniform sampler2D lit_contour_darkness;  // LINEAR, CLAMP_TO_EDGE
uniform sampler2DArray copy_inputs;      // per copy: offset_k(p), mix(1, t_k, texture_strength) (contour_copies.frag)
uniform sampler2D block_max;             // contour_blocks.frag
uniform float reach;                     // >= the largest |dx|, |dy| of any copy's offset

layout(location = 0) out float contour_darkness;

// Whether any texel a copy's bilinear read of d' can touch, (p - reach, p + reach) and
// the next texel, is in a block whose d' is not all 0. Clamp-to-edge keeps the texels
// read inside the clamped range.
bool contour_within_reach(vec2 p) {
  ivec2 last = textureSize(lit_contour_darkness, 0) - 1;
  ivec2 lo = clamp(ivec2(floor(p - reach - 0.5)), ivec2(0), last) / CONTOUR_BLOCK;
  ivec2 hi = clamp(ivec2(floor(p + reach - 0.5)) + 1, ivec2(0), last) / CONTOUR_BLOCK;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x)
      if (texelFetch(block_max, ivec2(x, y), 0).r != 0.0) return true;
  return false;
}

void main() {
  vec2 p = gl_FragCoord.xy;  // pixel center
  // Every d_k = 0 here, so D_c = 0, what the target was cleared to (gpu/multi_contour.cpp).
  // A discard, unlike a return, lets llvmpipe skip a block of pixels that all take it.
  if (!contour_within_reach(p)) discard;
  vec2 window = vec2(textureSize(lit_contour_darkness, 0));
  float untouched = 1.0;
  for (int k = 0; k < contour.copies; ++k) {
    vec3 copy = texelFetch(copy_inputs, ivec3(gl_FragCoord.xy, k), 0).xyz;
    float d_k = texture(lit_contour_darkness, (p + copy.xy) / window).r;
    untouched *= 1.0 - contour.stroke_opacity * d_k * copy.z;
  }
  contour_darkness = 1.0 - untouched;
}
