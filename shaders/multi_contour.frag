#version 450 core
// Multiple contour drawing (SPEC 2.4; Lee §4.2-4.3):
//   d_k = d'(p + offset_k(p)),  t_k = 1 - T_c(p / texture_scale + o_k)
//   D_c = 1 - prod_k (1 - alpha d_k mix(1, t_k, texture_strength))
const int MAX_COPIES = 8;
uniform sampler2D lit_contour_darkness;  // LINEAR, CLAMP_TO_EDGE
uniform sampler2DArray offset_grids;     // one RG layer per copy, LINEAR, CLAMP_TO_EDGE
uniform sampler2D contour_texture;       // LINEAR, REPEAT
uniform vec2 texture_shift[MAX_COPIES];  // o_k, texels

layout(location = 0) out float contour_darkness;

void main() {
  vec2 p = gl_FragCoord.xy;  // pixel center
  vec2 window = vec2(textureSize(lit_contour_darkness, 0));
  vec2 grid = vec2(textureSize(offset_grids, 0).xy);
  vec2 tex = vec2(textureSize(contour_texture, 0));
  float untouched = 1.0;
  for (int k = 0; k < contour.copies; ++k) {
    vec2 offset = texture(offset_grids, vec3((p / float(contour.grid_cell) + 0.5) / grid, float(k))).xy;
    float d_k = texture(lit_contour_darkness, (p + offset) / window).r;
    float t_k = 1.0 - texture(contour_texture, (p / contour.texture_scale + texture_shift[k]) / tex).r;
    untouched *= 1.0 - contour.stroke_opacity * d_k * (1.0 + (t_k - 1.0) * contour.texture_strength);
  }
  contour_darkness = 1.0 - untouched;
}
