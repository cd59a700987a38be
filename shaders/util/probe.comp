#version 450 core
// Limit probes (gpu/core/limits.hpp): the compute twins of probe.frag, one invocation a pixel.
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform writeonly image2D target;
#ifdef FETCH3X3
uniform sampler2D source;
#endif

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy), size = imageSize(target);
  if (p.x >= size.x || p.y >= size.y) return;
#ifdef FETCH3X3
  float sum = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) sum += texelFetch(source, clamp(p + ivec2(x, y), ivec2(0), size - 1), 0).r;
  imageStore(target, p, vec4(sum));
#else
  imageStore(target, p, vec4(1.0));
#endif
}
