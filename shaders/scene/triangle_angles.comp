#version 450 core
// Texture rotation (Lee et al. 2006, §5.3), after corner_angles.comp: each triangle's record of its
// three corners' stroke angles, what the G-buffer's theta channels hold at its pixels. The
// G-buffer's vertices and the pencil interior read these records.
layout(local_size_x = 64) in;

layout(std430, binding = 1) readonly buffer Angles { vec2 vertex_angles[]; };          // theta_min, theta_max
layout(std430, binding = 2) readonly buffer Triangles { uint triangle_vertices[]; };   // 3 a triangle
layout(std430, binding = 3) writeonly buffer TriangleAngles { vec4 triangle_angles[]; };  // 2 a triangle
uniform uint triangle_count;
uniform uint first_triangle;  // this object's first record
uniform uint first;           // of this dispatch (gpu/gl/program.hpp dispatch_in_chunks)

void main() {
  uint t = first + gl_GlobalInvocationID.x;
  if (t >= triangle_count) return;
  vec2 a0 = vertex_angles[triangle_vertices[3u * t]], a1 = vertex_angles[triangle_vertices[3u * t + 1u]],
       a2 = vertex_angles[triangle_vertices[3u * t + 2u]];
  triangle_angles[2u * (first_triangle + t)] = vec4(a0.x, a1.x, a2.x, 0.0);
  triangle_angles[2u * (first_triangle + t) + 1u] = vec4(a0.y, a1.y, a2.y, 0.0);
}
