// Edge detection (Nienhaus & Döllner 2003, as given in Pacheco §2) at one pixel: contour darkness d = 1 - I_n I_z from
// the diagonal neighbors A C / F H, y up (window coordinates), clamp-to-edge. Shared by
// edge_detect.frag and sketchy_maps.frag.
uniform sampler2D normals;  // view-space normals (shading or face, chosen on the CPU), w: linear view depth
uniform float near_plane;
uniform float far_plane;

ivec2 clamped(ivec2 p) { return clamp(p, ivec2(0), textureSize(normals, 0) - 1); }
// xyz: the normal, w: the linear view depth (gbuffer.frag writes it next to the normals
// so that the filter reads one texel per neighbor).
vec4 normal_and_depth_at(ivec2 p) { return texelFetch(normals, clamped(p), 0); }
float normalized_depth(float d) { return (d - near_plane) / (far_plane - near_plane); }

// N_1.N_2; two background pixels (zero normals) count as continuous unless the
// literal formula is asked for (common/pencil/edge_detect.hpp).
float normal_agreement(vec3 n1, vec3 n2) {
  bool both_background = dot(n1, n1) == 0.0 && dot(n2, n2) == 0.0;
  return both_background && edge.background_pairs == EDGE_BACKGROUND_PAIRS_CONTINUOUS ? 1.0 : dot(n1, n2);
}

float depth_factor(float z1, float z2) {
  float f = 1.0 - min(1.0, 0.5 * edge.depth_scale * abs(z1 - z2));
  return f * f;
}

float contour_darkness_at(ivec2 x) {
  vec4 a = normal_and_depth_at(x + ivec2(-1, 1)), h = normal_and_depth_at(x + ivec2(1, -1));
  vec4 c = normal_and_depth_at(x + ivec2(1, 1)), f = normal_and_depth_at(x + ivec2(-1, -1));
  float i_n = clamp(0.5 * (normal_agreement(a.xyz, h.xyz) + normal_agreement(c.xyz, f.xyz)), 0.0, 1.0);
  float i_z = depth_factor(normalized_depth(a.w), normalized_depth(h.w)) *
              depth_factor(normalized_depth(c.w), normalized_depth(f.w));
  return 1.0 - i_n * i_z;
}
