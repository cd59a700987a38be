#version 450 core
// The mark of each CONTOUR_BLOCK x CONTOUR_BLOCK block of pixels: 1 where some d' > 0, else
// 0, for multi_contour.frag to find the pixels no copy can darken (a GPU shortcut, not a
// stage of docs/stages.md: the reference computes every pixel). A frame marks the blocks while it
// draws d' instead (edge_detect.frag).
uniform sampler2D lit_contour_darkness;

layout(location = 0) out float block_mark;

void main() {
  ivec2 last = textureSize(lit_contour_darkness, 0) - 1;
  ivec2 first = ivec2(gl_FragCoord.xy) * CONTOUR_BLOCK;
  float m = 0.0;
  for (int y = 0; y < CONTOUR_BLOCK; ++y)
    for (int x = 0; x < CONTOUR_BLOCK; ++x)
      m = max(m, texelFetch(lit_contour_darkness, min(first + ivec2(x, y), last), 0).r);
  block_mark = m > 0.0 ? 1.0 : 0.0;
}
