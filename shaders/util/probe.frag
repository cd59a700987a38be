#version 450 core
// Limit probes (gpu/core/limits.hpp): a full-screen fragment pass that writes a constant, or
// (FETCH3X3) the sum of the 3x3 texels around its pixel: the cheapest passes of their kind.
#ifdef FETCH3X3
uniform sampler2D source;
#endif
out float value;

void main() {
#ifdef FETCH3X3
  ivec2 p = ivec2(gl_FragCoord.xy), last = textureSize(source, 0) - 1;
  float sum = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) sum += texelFetch(source, clamp(p + ivec2(x, y), ivec2(0), last), 0).r;
  value = sum;
#else
  value = 1.0;
#endif
}
