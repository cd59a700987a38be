#version 450 core
// Composition and enhancement (SPEC 2.11, Lee Eq. 6); white paper, no interior yet.
uniform sampler2D contour_darkness;

layout(location = 0) out vec4 color;

// I = (1 - D_c)(1 - D_i'), D_i' = D_i (1 - a D_c)
float composed_intensity(float d_c, float d_i) {
  float attenuated = d_i * (1.0 - compose.contour_attenuation * d_c);
  return (1.0 - d_c) * (1.0 - attenuated);
}

// I'' = mix(I, smoothstep(0, 1, I), contrast)
float enhanced(float i) { return i + (smoothstep(0.0, 1.0, i) - i) * compose.contrast; }

void main() {
  float d_c = texelFetch(contour_darkness, ivec2(gl_FragCoord.xy), 0).r;
  color = vec4(vec3(enhanced(composed_intensity(d_c, 0.0))), 1.0);
}
