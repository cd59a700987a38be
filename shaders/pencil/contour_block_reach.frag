#version 450 core
// Whether any block within `block_reach` blocks of this one is marked (contour_blocks.frag or
// edge_detect.frag mark the blocks with some d' > 0): 1 or 0. Multiple contour drawing
// skips the pixels of a block where it is 0, since no copy of any of them reads farther
// than that (common_multi_contour.glsl).
uniform sampler2D block_marks;
uniform int block_reach;

layout(location = 0) out float reach_max;

void main() {
  ivec2 block = ivec2(gl_FragCoord.xy), last = textureSize(block_marks, 0) - 1;
  float m = 0.0;
  for (int y = -block_reach; y <= block_reach; ++y)
    for (int x = -block_reach; x <= block_reach; ++x)
      m = max(m, texelFetch(block_marks, clamp(block + ivec2(x, y), ivec2(0), last), 0).r);
  reach_max = m;
}
