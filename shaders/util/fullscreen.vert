#version 450 core
// One triangle covering the window; fragments run at every pixel center. Its depth is
// FULLSCREEN_Z in normalized device coordinates (0 unless a program defines it).
#ifndef FULLSCREEN_Z
#define FULLSCREEN_Z 0.0
#endif
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, FULLSCREEN_Z, 1.0);
}
