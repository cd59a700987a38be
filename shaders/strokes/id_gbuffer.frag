#version 450 core
// The ID image's faces from the G-buffer (common/strokes/id_image.hpp rule 1): at each pixel an
// object covers, its face key at depth z = near / d, d the G-buffer's depth there.
uniform usampler2D ids;  // G-buffer: object index + 1 (0: background), triangle index
uniform sampler2D depth;  // G-buffer: linear view depth d
uniform float near;
layout(std430, binding = 0) readonly buffer FirstKeys { uint first_key[]; };  // per G-buffer object
layout(location = 0) out uvec2 halves;
layout(location = 1) out uvec2 crease_halves;  // id_image.crease_ids: not drawn to by the silhouettes

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  uvec2 id = texelFetch(ids, x, 0).xy;
  if (id.x == 0u) discard;
  uint key = first_key[id.x - 1u] + id.y;
  gl_FragDepth = near / max(texelFetch(depth, x, 0).r, near);
  halves = uvec2(key >> 16, key & 0xffffu);
  crease_halves = halves;
}
