#version 450 core
// The ID image's triangles (SPEC 4.4), pulled from a buffer of window-space vertices
// (common/id_image.hpp IdVertex): depth is z = near / d, written as is (glClipControl
// GL_ZERO_TO_ONE) and tested GL_GREATER.
struct IdVertex {
  vec2 window;
  float z;
  uint key;
};
layout(std430, binding = 0) readonly buffer Vertices { IdVertex vertices[]; };
uniform vec2 window_size;
flat out uint key;

void main() {
  IdVertex v = vertices[gl_VertexID];
  gl_Position = vec4(v.window / window_size * 2.0 - 1.0, v.z, 1.0);
  key = v.key;
}
