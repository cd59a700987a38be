#version 450 core
// Interior pencil shading (SPEC 2.6-2.10), formulas in common/pencil_interior.hpp.
uniform sampler2D interior_intensity;
uniform sampler2D bary;
uniform sampler2D theta_min;
uniform sampler2D theta_max;
uniform usampler2D ids;
uniform sampler3D pencil_stack;   // LINEAR; REPEAT in s, t; CLAMP_TO_EDGE in r
uniform sampler2D paper_normal;   // read texel for pixel, wrapping
uniform bool crosshatch;
uniform bool paper_effect;
uniform float mu_p;

layout(location = 0) out float interior_darkness;

// c_k = P(R(-theta) p / texture_scale, r), then the paper effect c_k' (2.7, 2.10)
float corner_sample(vec2 p, float theta, float r, vec3 n) {
  float c = cos(theta), s = sin(theta);
  vec2 uv = vec2(c * p.x + s * p.y, -s * p.x + c * p.y) / interior.texture_scale;
  float tone = texture(pencil_stack, vec3(uv / float(textureSize(pencil_stack, 0).x), r)).r;
  return paper_effect ? clamp(tone + mu_p * dot(vec3(c, s, 0.0), n), 0.0, 1.0) : tone;
}

// c = w0 c_0' + w1 c_1' + w2 c_2' (2.8)
float blended(vec2 p, vec3 w, vec3 theta, float r, vec3 n) {
  return w.x * corner_sample(p, theta.x, r, n) + w.y * corner_sample(p, theta.y, r, n) +
         w.z * corner_sample(p, theta.z, r, n);
}

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  if (texelFetch(ids, x, 0).r == 0u) {
    interior_darkness = 0.0;
    return;
  }
  float i = texelFetch(interior_intensity, x, 0).r;
  float layers = float(textureSize(pencil_stack, 0).z);
  float r = ((1.0 - i) * (layers - 1.0) + 0.5) / layers;  // tone to layer (2.6)
  vec2 p = gl_FragCoord.xy;
  vec3 w = texelFetch(bary, x, 0).xyz;
  vec3 n = paper_effect ? texelFetch(paper_normal, x % textureSize(paper_normal, 0), 0).xyz : vec3(0.0);
  float c = blended(p, w, texelFetch(theta_min, x, 0).xyz, r, n);
  float h = crosshatch ? 1.0 - smoothstep(interior.crosshatch_below - interior.crosshatch_band, interior.crosshatch_below, i) : 0.0;
  if (h > 0.0) c *= 1.0 + (blended(p, w, texelFetch(theta_max, x, 0).xyz, r, n) - 1.0) * h;  // (2.9)
  interior_darkness = 1.0 - c;
}
