#version 450 core
// The ID image's key as two 16-bit halves (common/strokes/id_image.hpp), at depth z = near / d:
// a line's z comes affinely interpolated (shaders/strokes/id_lines.vert), a face's from its
// perspective-correct d (FACES, shaders/strokes/id_faces.vert).
#ifdef FACES
in float d;
uniform float near;
float z() { return near / max(d, near); }
#else
noperspective in float z_line;
float z() { return z_line; }
#endif
flat in uint key;
layout(location = 0) out uvec2 halves;
layout(location = 1) out uvec2 crease_halves;  // id_image.crease_ids: not drawn to by the silhouettes

void main() {
  gl_FragDepth = z();
  halves = uvec2(key >> 16, key & 0xffffu);
  crease_halves = halves;
}
