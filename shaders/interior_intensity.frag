#version 450 core
// Interior intensity and brightness (SPEC 2.5): Gouraud or Phong, then I' = sqrt(I).
#include "common_lights.glsl"

uniform sampler2D gouraud;
uniform sampler2D normals;
uniform usampler2D ids;

layout(location = 0) out float interior_intensity;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  if (texelFetch(ids, p, 0).r == 0u) {
    interior_intensity = 1.0;
    return;
  }
  float i = interior.shading == INTERIOR_SHADING_GOURAUD
                ? texelFetch(gouraud, p, 0).r
                : clamp(interior.ambient + interior.diffuse * light_sum(texelFetch(normals, p, 0).xyz), 0.0, 1.0);
  interior_intensity = interior.brightness_sqrt ? sqrt(i) : i;
}
