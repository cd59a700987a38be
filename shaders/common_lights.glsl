// The scene's lights in view space (common/interior.hpp: view_space_lights) and the
// Lambert intensity of SPEC 2.5, I = clamp(k_a + k_d sum intensity max(0, n.L)).
const int MAX_LIGHTS = 8;
uniform int light_count;
uniform vec3 light_direction[MAX_LIGHTS];  // unit, towards the light
uniform float light_intensity[MAX_LIGHTS];

float lambert_intensity(vec3 n) {
  float sum = 0.0;
  for (int i = 0; i < light_count; ++i) sum += light_intensity[i] * max(0.0, dot(n, light_direction[i]));
  return clamp(interior.ambient + interior.diffuse * sum, 0.0, 1.0);
}
