#version 450 core
// The G-buffer's background values (docs/stages.md, gbuffer), drawn where no object is: after the objects,
// at the far plane, with GL_LEQUAL (gpu/scene/gbuffer.cpp draw_background).
uniform float far_plane;

layout(location = 0) out vec4 out_normal;
layout(location = 1) out vec4 out_face_normal;
layout(location = 2) out float out_depth;
layout(location = 3) out uvec2 out_ids;
layout(location = 4) out vec4 out_bary;
layout(location = 5) out float out_gouraud;
layout(location = 6) out vec4 out_theta_min;
layout(location = 7) out vec4 out_theta_max;

void main() {
  out_normal = out_face_normal = vec4(0.0, 0.0, 0.0, far_plane);  // w: the depth, next to the normal
  out_depth = far_plane;
  out_ids = uvec2(0u);  // no object
  out_bary = vec4(0.0);
  out_gouraud = 1.0;
  out_theta_min = out_theta_max = vec4(0.0);
}
