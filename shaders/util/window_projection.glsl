// An object point's window position and linear view depth (docs/conventions.md), in float:
// the uniforms of gpu/scene/mesh_buffers.hpp object_uniforms and the window's size.
uniform mat4 clip;       // object to clip space
uniform vec4 depth_row;  // object point (x, 1) to linear view depth
uniform vec2 window_size;

// (x, y) in pixels, origin bottom-left, and d = -z_view.
vec3 project(vec3 p) {
  vec4 c = clip * vec4(p, 1.0);
  return vec3((c.xy / c.w * 0.5 + 0.5) * window_size, dot(depth_row, vec4(p, 1.0)));
}
