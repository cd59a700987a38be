#version 450 core
// The stroke ribbons' triangles (Kalnins et al. 2002, §4.1), pulled from a buffer of window-space
// vertices (common/strokes/stroke.hpp StrokeVertex: 9 floats). Attributes are affine in the window.
layout(std430, binding = 0) readonly buffer Vertices { float vertices[]; };
uniform vec2 window_size;
noperspective out vec2 uv;
noperspective out float alpha;
flat out vec3 color;
flat out float layer;

void main() {
  int b = gl_VertexID * 9;
  vec2 window = vec2(vertices[b], vertices[b + 1]);
  gl_Position = vec4(window / window_size * 2.0 - 1.0, 0.0, 1.0);
  uv = vec2(vertices[b + 2], vertices[b + 3]);
  alpha = vertices[b + 4];
  color = vec3(vertices[b + 5], vertices[b + 6], vertices[b + 7]);
  layer = vertices[b + 8];
}
