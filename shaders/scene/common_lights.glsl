// The scene's lights in view space (common/scene/lights.hpp: view_space_lights) and
// light_sum(n) = sum intensity max(0, n.L) (common/scene/lights.cpp).
const int MAX_LIGHTS = 8;
uniform int light_count;
uniform vec3 light_direction[MAX_LIGHTS];  // unit, towards the light
uniform float light_intensity[MAX_LIGHTS];

float light_sum(vec3 n) {
  float sum = 0.0;
  for (int i = 0; i < light_count; ++i) sum += light_intensity[i] * max(0.0, dot(n, light_direction[i]));
  return sum;
}
