#version 450 core
// The largest lit contour darkness d' in each CONTOUR_BLOCK x CONTOUR_BLOCK block of
// pixels, for multi_contour.frag to find the pixels no copy can darken (a GPU shortcut,
// not a stage of SPEC: the reference computes every pixel).
uniform sampler2D lit_contour_darkness;

layout(location = 0) out float block_max;

void main() {
  ivec2 last = textureSize(lit_contour_darkness, 0) - 1;
  ivec2 first = ivec2(gl_FragCoord.xy) * CONTOUR_BLOCK;
  float m = 0.0;
  for (int y = 0; y < CONTOUR_BLOCK; ++y)
    for (int x = 0; x < CONTOUR_BLOCK; ++x) m = max(m, texelFetch(lit_contour_darkness, min(first + ivec2(x, y), last), 0).r);
  block_max = m;
}
