#version 450 core
// One point per quad of the ID image's lines: its index, for strokes/id_lines.geom.
flat out uint quad;

void main() {
  quad = uint(gl_VertexID);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
