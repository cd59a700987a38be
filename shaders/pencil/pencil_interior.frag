#version 450 core
// Interior intensity and brightness (Lee et al. 2006, §3, §5.2) and interior pencil shading (Lee et al. 2006, §5.1-5.5)
// in one pass: D_i is the output, and I' a second one for a dump. Formulas in common/pencil/interior_intensity.hpp
// and common/pencil/pencil_interior.hpp.
#include "scene/common_lights.glsl"
#include "util/common_wrap.glsl"

uniform sampler2D normals;
uniform sampler2D bary;           // w: the Gouraud intensity
uniform usampler2D ids;            // object id, triangle index
// Per triangle, its corners' stroke angles (gpu/scene/gbuffer.hpp TriangleAngles): theta_min,
// then theta_max, what the G-buffer's angle channels hold at its pixels.
layout(std430, binding = 0) readonly buffer TriangleAngles { vec4 triangle_angles[]; };
layout(std430, binding = 1) readonly buffer FirstTriangle { uint first_triangle[]; };  // per object
uniform sampler3D pencil_stack;   // LINEAR; REPEAT in s, t; CLAMP_TO_EDGE in r
uniform sampler2D paper_normal;   // read texel for pixel, wrapping
uniform float mu_p;
// The choices are compiled in (gpu/pencil/pencil_interior.cpp): llvmpipe runs both sides of an if,
// even on a uniform, so a Gouraud frame would pay for the Phong normal's fetch and lights.
const bool phong = PHONG != 0, nearest_corner = NEAREST_CORNER != 0;
const bool crosshatch = CROSSHATCH != 0, paper_effect = PAPER_EFFECT != 0;

layout(location = 0) out float interior_darkness;
#if WRITE_INTENSITY
layout(location = 1) out float interior_intensity;  // for a dump: a frame does not keep I'
#endif

// I' = sqrt(I), I Gouraud or Phong (Lee et al. 2006, §3, §5.2)
float adjusted_intensity(ivec2 x, float gouraud) {
  float i = phong ? clamp(interior.ambient + interior.diffuse * light_sum(texelFetch(normals, x, 0).xyz), 0.0, 1.0)
                  : gouraud;
  return interior.brightness_sqrt ? sqrt(i) : i;
}

// c_k = P(R(-theta) p / texture_scale, r), then the paper effect c_k' (2.7, 2.10)
float corner_sample(vec2 p, float theta, float r, vec3 n) {
  float c = cos(theta), s = sin(theta);
  vec2 uv = vec2(c * p.x + s * p.y, -s * p.x + c * p.y) / interior.texture_scale;
  float tone = texture(pencil_stack, vec3(uv / float(textureSize(pencil_stack, 0).x), r)).r;
  return paper_effect ? clamp(tone + mu_p * dot(vec3(c, s, 0.0), n), 0.0, 1.0) : tone;
}

// The corners' weights: the barycentrics, or a one-hot of the largest (common/pencil/interior_intensity.hpp).
vec3 blend_weights(vec3 w) {
  if (!nearest_corner) return w;
  if (w.x >= w.y && w.x >= w.z) return vec3(1.0, 0.0, 0.0);
  return w.y >= w.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
}

// c = w0 c_0' + w1 c_1' + w2 c_2' (2.8), corners of weight 0 not sampled.
float blended(vec2 p, vec3 barycentrics, vec3 theta, float r, vec3 n) {
  vec3 w = blend_weights(barycentrics);
  float c = 0.0;
  for (int k = 0; k < 3; ++k)
    if (w[k] != 0.0) c += w[k] * corner_sample(p, theta[k], r, n);
  return c;
}

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  // Background: the targets already hold D_i = 0, I' = 1 (FullscreenPass::draw_inside). A
  // discard, unlike a return, lets llvmpipe skip a block of pixels that are all background.
  uvec2 id = texelFetch(ids, x, 0).rg;
  if (id.r == 0u) discard;
  uint triangle = first_triangle[id.r - 1u] + id.g;
  vec4 bary_gouraud = texelFetch(bary, x, 0);
  float i = adjusted_intensity(x, bary_gouraud.w);
#if WRITE_INTENSITY
  interior_intensity = i;
#endif
  float layers = float(textureSize(pencil_stack, 0).z);
  float r = ((1.0 - i) * (layers - 1.0) + 0.5) / layers;  // tone to layer (2.6)
  vec2 p = gl_FragCoord.xy;
  vec3 w = bary_gouraud.xyz;
  vec3 n = paper_effect ? texelFetch(paper_normal, wrapped_texel(x, textureSize(paper_normal, 0)), 0).xyz : vec3(0.0);
  float h = crosshatch
                ? 1.0 - smoothstep(interior.crosshatch_below - interior.crosshatch_band, interior.crosshatch_below, i)
                : 0.0;
  // c with the min-curvature angles, then times 1 + (c_max - 1) h where h > 0 (2.9). A
  // loop, not an if: llvmpipe leaves a loop once no pixel of a block runs it, but runs
  // both sides of an if, so unhatched blocks would pay for the hatching.
  float c = 1.0;
  for (int k = 0; k < (h > 0.0 ? 2 : 1); ++k) {
    float b = blended(p, w, triangle_angles[2u * triangle + uint(k)].xyz, r, n);  // k = 0: theta_min, 1: theta_max
    c = k == 0 ? b : c * (1.0 + (b - 1.0) * h);
  }
  interior_darkness = 1.0 - c;
}
