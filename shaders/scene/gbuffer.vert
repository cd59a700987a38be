#version 450 core
// G-buffer (docs/stages.md, gbuffer): world-space triangle soup, one vertex per triangle corner.
layout(location = 0) in vec3 position;     // world
layout(location = 1) in vec3 normal;       // world, unit (shading)
layout(location = 2) in vec3 face_normal;  // world, unit (geometric)
layout(location = 3) in vec3 corner;       // (1,0,0), (0,1,0) or (0,0,1)
layout(location = 4) in float gouraud;     // Lee et al. 2006, §3, §5.2, per vertex
// Per triangle, its corners' stroke angles this frame (triangle_angles.comp, Lee et al. 2006, §5.3):
// theta_min, then theta_max; zero without curvature.
layout(std430, binding = 1) readonly buffer TriangleAngles { vec4 triangle_angles[]; };
uniform uint first_triangle;  // this object's first record; soup vertex i is a corner of triangle i / 3

uniform mat4 view;
uniform mat4 projection;

out vec3 v_normal;
flat out vec3 v_face_normal;  // the same at the three corners
out vec3 v_bary;
out float v_depth;
out float v_gouraud;
flat out vec3 v_theta_min;
flat out vec3 v_theta_max;

void main() {
  vec4 view_position = view * vec4(position, 1.0);
  gl_Position = projection * view_position;
  v_normal = mat3(view) * normal;
  v_face_normal = mat3(view) * face_normal;
  v_bary = corner;
  v_depth = -view_position.z;  // linear view depth d = -z_view (docs/conventions.md)
  v_gouraud = gouraud;
  v_theta_min = v_theta_max = vec3(0.0);
#if WRITE_THETA_MIN || WRITE_THETA_MAX
  uint t = first_triangle + uint(gl_VertexID) / 3u;
  v_theta_min = triangle_angles[2u * t].xyz;
  v_theta_max = triangle_angles[2u * t + 1u].xyz;
#endif
}
