#version 450 core
// The ID image's key as two 16-bit halves (common/strokes/id_image.hpp), at depth z = near / d.
noperspective in float z;
flat in uint key;
layout(location = 0) out uvec2 halves;

void main() {
  gl_FragDepth = z;
  halves = uvec2(key >> 16, key & 0xffffu);
}
