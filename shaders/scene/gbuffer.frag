#version 450 core
// G-buffer (docs/stages.md, gbuffer). Perspective-correct interpolation gives the same barycentrics as
// the ray tracer's hit coordinates; normals are normalized after interpolation.
in vec3 v_normal;
flat in vec3 v_face_normal;
in vec3 v_bary;
in float v_depth;
in float v_gouraud;
flat in vec3 v_theta_min;
flat in vec3 v_theta_max;

uniform uint object_id;  // object index + 1

layout(location = 0) out vec4 out_normal;
layout(location = 1) out vec4 out_face_normal;
layout(location = 2) out float out_depth;
layout(location = 3) out uvec2 out_ids;
layout(location = 4) out vec4 out_bary;
layout(location = 5) out float out_gouraud;
layout(location = 6) out vec4 out_theta_min;
layout(location = 7) out vec4 out_theta_max;

vec3 unit_or_zero(vec3 v) {
  float len = length(v);
  return len > 0.0 ? v / len : vec3(0.0);
}

// Ids are always written; the other targets only by the program variant whose
// WRITE_* flag is 1 (gpu/scene/gbuffer.cpp GBufferChannels): on llvmpipe an output computed but
// sent to GL_NONE still costs its interpolation and shading.
void main() {
#if WRITE_DEPTH
  out_depth = v_depth;
#endif
  out_ids = uvec2(object_id, uint(gl_PrimitiveID));
#if WRITE_NORMAL
  out_normal = vec4(unit_or_zero(v_normal), v_depth);  // w: for the edge filter (common_edge.glsl)
#endif
#if WRITE_FACE_NORMAL
  out_face_normal = vec4(unit_or_zero(v_face_normal), v_depth);
#endif
#if WRITE_BARY
  out_bary = vec4(v_bary, v_gouraud);  // w: for the interior (pencil_interior.frag)
#endif
#if WRITE_GOURAUD
  out_gouraud = v_gouraud;
#endif
#if WRITE_THETA_MIN
  out_theta_min = vec4(v_theta_min, 0.0);
#endif
#if WRITE_THETA_MAX
  out_theta_max = vec4(v_theta_max, 0.0);
#endif
}
