// Texture rotation (Lee et al. 2006, §5.3), the formula of common/curvature/texture_rotation.cpp:
//   c = M (p, 1), e = M (d, 0), J d = (W/2, H/2) (e.xy c.w - c.xy e.w) / c.w^2
// A direction shorter than min_projected x H / (2 tan(fov/2) c.w) is not trusted.
uniform mat4 view_projection;
uniform vec2 window_size;
uniform float tan_half_fov;

// xy: theta, z: 1 when reliable.
vec2 window_angle(vec3 p, vec3 d) {
  vec4 c = view_projection * vec4(p, 1.0);
  vec4 e = view_projection * vec4(d, 0.0);
  vec2 jd = window_size * 0.5 * (e.xy * c.w - c.xy * e.w) / (c.w * c.w);
  float across = window_size.y / (2.0 * tan_half_fov * c.w);
  bool reliable = c.w > 0.0 && length(jd) >= interior.min_projected * across;
  return reliable ? vec2(atan(jd.y, jd.x), 1.0) : vec2(0.0);
}

float stroke_angle(vec3 p, vec3 primary, vec3 secondary) {
  vec2 a = window_angle(p, primary);
  if (a.y > 0.0) return a.x;
  vec2 b = window_angle(p, secondary);
  return b.y > 0.0 ? b.x + 1.5707963 : 0.0;
}
