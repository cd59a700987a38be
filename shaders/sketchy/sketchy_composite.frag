#version 450 core
// Sketchy composite and depth sprite (Nienhaus & Döllner §3.2-3.4, §4),
// the twin of reference/sketchy/sketchy_composite.cpp. Drawn over what the ordinary objects left
// in the color and depth buffers; the depth test orders the two.
uniform sampler2D edge_map;           // RG: contour darkness (filtered), edge depth (nearest)
uniform sampler2D shade_map;          // RGBA: unlit color, alpha = coverage
uniform sampler2D depth;              // the sketchy objects' linear depth
uniform sampler2D noise;              // Perlin in [-1, 1], LINEAR, REPEAT
uniform sampler2D white_noise;        // rough style: RG uniform in [0, 1)
uniform sampler3D noise_3d;           // object style: Perlin in [-1, 1], LINEAR, REPEAT
uniform sampler2D noise_coordinates;  // object style: enlarged surface's noise coordinate, alpha = coverage
#include "util/common_wrap.glsl"
uniform float near_plane;
uniform float far_plane;
uniform mat2 shade_matrix;            // M_s
uniform mat2 copy_matrices[8];        // M_e turned per edge copy; [0] = M_e
uniform vec3 copy_inks[8];
uniform vec2 copy_shifts[8];

layout(location = 0) out vec4 color;
layout(location = 1) out float sprite_depth;  // normalized, where drawn

// T(s, t) = sum_i |N(2^i (s, t))| / 2^i (Nienhaus & Döllner 2004, §3.2)
float turbulence(vec2 st) {
  float t = 0.0, f = 1.0;
  for (int i = 0; i < sketchy.octaves; ++i, f *= 2.0) t += abs(texture(noise, st * f).r) / f;
  return t;
}

float turbulence(vec3 q) {
  float t = 0.0, f = 1.0;
  for (int i = 0; i < sketchy.octaves; ++i, f *= 2.0) t += abs(texture(noise_3d, q * f).r) / f;
  return t;
}

// (u, v) of Nienhaus & Döllner 2004, §3.2 at the pixel for edge copy k, centered on 0.
vec2 uncertainty(vec2 center, int k) {
  ivec2 x = ivec2(center);
  if (sketchy.style == SKETCHY_STYLE_ROUGH)
    return texelFetch(white_noise, wrapped_texel(x, textureSize(white_noise, 0)), 0).rg - 0.5;
  if (sketchy.style == SKETCHY_STYLE_OBJECT) {
    vec4 g = texelFetch(noise_coordinates, x, 0);
    if (g.a == 0.0) return vec2(0.0);
    vec3 q = g.xyz / sketchy.object_noise_scale;
    return vec2(turbulence(q), turbulence(1.0 - q)) - 0.5;
  }
  vec2 st = center / sketchy.noise_scale + copy_shifts[k];
  return vec2(turbulence(st), turbulence(1.0 - st)) - 0.5;
}

ivec2 nearest_texel(sampler2D map, vec2 q) { return clamp(ivec2(floor(q)), ivec2(0), textureSize(map, 0) - 1); }

struct EdgeSample {
  float darkness, depth;
  bool dark;
};

// e = edge(p + delta_e): darkness filtered, its depth from the nearest texel.
EdgeSample edge_sample(vec2 q) {
  EdgeSample e;
  e.darkness = texture(edge_map, q / vec2(textureSize(edge_map, 0))).r;
  e.depth = texelFetch(edge_map, nearest_texel(edge_map, q), 0).g;
  e.dark = e.darkness > sketchy.dark_edge && e.depth < far_plane;
  return e;
}

// Linear depth as the window depth a perspective projection gives it.
float window_depth(float d) {
  float ndc = (far_plane + near_plane) / (far_plane - near_plane) -
              2.0 * far_plane * near_plane / ((far_plane - near_plane) * d);
  return 0.5 * ndc + 0.5;
}

void main() {
  vec2 center = gl_FragCoord.xy;
  bool drawn = false;
  float d = far_plane;
  vec3 c = vec3(1.0);
  if (sketchy.style == SKETCHY_STYLE_REPEAT) {  // edge copies, each its own matrix and ink
    for (int k = 0; k < sketchy.edge_copies; ++k) {
      EdgeSample e = edge_sample(center + copy_matrices[k] * uncertainty(center, k));
      if (!e.dark) continue;
      drawn = true;
      d = min(d, e.depth);
      c *= mix(copy_inks[k], vec3(1.0), 1.0 - e.darkness);
    }
  } else {  // e * c.rgb inside the shade map, e * white outside (Nienhaus & Döllner 2004, §3.2)
    vec2 uv = uncertainty(center, 0);
    EdgeSample e = edge_sample(center + copy_matrices[0] * uv);
    ivec2 s = nearest_texel(shade_map, center + shade_matrix * uv);
    vec4 shade = texelFetch(shade_map, s, 0);
    bool interior = shade.a > 0.5;
    drawn = e.dark || interior;
    d = min(e.dark ? e.depth : far_plane, interior ? texelFetch(depth, s, 0).r : far_plane);
    c = (1.0 - e.darkness) * (interior ? shade.rgb : vec3(1.0));
  }
  if (!drawn || !(d < far_plane)) discard;  // both samples exterior: rejected early
  color = vec4(c, 1.0);
  sprite_depth = (d - near_plane) / (far_plane - near_plane);
  gl_FragDepth = window_depth(d);  // the depth sprite (Nienhaus & Döllner 2004, §3.3)
}
