#version 450 core
// The largest d' of the blocks within `block_reach` blocks of this one (contour_blocks.frag
// gives each block's own): multi_contour.frag discards the pixels of a block where it is 0,
// since no copy of any of them reads farther than that.
uniform sampler2D block_max;
uniform int block_reach;

layout(location = 0) out float reach_max;

void main() {
  ivec2 block = ivec2(gl_FragCoord.xy), last = textureSize(block_max, 0) - 1;
  float m = 0.0;
  for (int y = -block_reach; y <= block_reach; ++y)
    for (int x = -block_reach; x <= block_reach; ++x) m = max(m, texelFetch(block_max, clamp(block + ivec2(x, y), ivec2(0), last), 0).r);
  reach_max = m;
}
