// The texel of a repeating texture of `size` texels under pixel x (paper, white noise:
// one texel per pixel). x mod size in float, exact below 2^24: llvmpipe computes an
// integer % one lane at a time.
ivec2 wrapped_texel(ivec2 x, ivec2 size) {
  vec2 p = vec2(x), s = vec2(size);
  return ivec2(p - s * floor(p / s));
}
