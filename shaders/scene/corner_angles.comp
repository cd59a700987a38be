#version 450 core
// Texture rotation (Lee et al. 2006, §5.3), once a frame before the G-buffer: per mesh vertex, the
// window-space angles of its min- and max-curvature strokes (common_rotation.glsl), which
// triangle_angles.comp gathers per triangle.
layout(local_size_x = 64) in;
#include "pencil/common_rotation.glsl"

struct VertexCurvature {
  vec4 position, d_min, d_max;  // world space; w unused
};
layout(std430, binding = 0) readonly buffer Curvatures { VertexCurvature vertex_curvature[]; };
layout(std430, binding = 1) writeonly buffer Angles { vec2 vertex_angles[]; };  // theta_min, theta_max
uniform uint vertex_count;
uniform uint first;  // of this dispatch (gpu/gl/program.hpp dispatch_in_chunks)

void main() {
  uint v = first + gl_GlobalInvocationID.x;
  if (v >= vertex_count) return;
  VertexCurvature c = vertex_curvature[v];
  vertex_angles[v] = vec2(stroke_angle(c.position.xyz, c.d_min.xyz, c.d_max.xyz),
                          stroke_angle(c.position.xyz, c.d_max.xyz, c.d_min.xyz));
}
