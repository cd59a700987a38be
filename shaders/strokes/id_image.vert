#version 450 core
// The ID image's triangles (Kalnins et al. 2002, §4.6), pulled from a buffer of window-space vertices
// (common/strokes/id_image.hpp IdVertex). z = near / d is interpolated affinely (noperspective)
// and written as the fragment's depth as it is (no [-1, 1] round trip, whose 2z - 1 would
// lose the precision of small z), then tested GL_GREATER.
struct IdVertex {
  vec2 window;
  float z;
  uint key;
};
layout(std430, binding = 0) readonly buffer Vertices { IdVertex vertices[]; };
uniform vec2 window_size;
noperspective out float z_line;
flat out uint key;

void main() {
  IdVertex v = vertices[gl_VertexID];
  gl_Position = vec4(v.window / window_size * 2.0 - 1.0, 0.0, 1.0);
  z_line = v.z;
  key = v.key;
}
