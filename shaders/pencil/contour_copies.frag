#version 450 core
// What multiple contour drawing (multi_contour.frag, Lee et al. 2006, §4.2-4.3) reads for copy k at a
// pixel that does not change from frame to frame, computed once per window size and
// parameters: the copy's offset (Eq. 2, bilinear between the grid's vertices) and its
// texture factor mix(1, t_k, texture_strength), t_k = 1 - T_c(p / texture_scale + o_k).
uniform sampler2DArray offset_grids;  // one RG layer per copy, LINEAR, CLAMP_TO_EDGE
uniform sampler2D contour_texture;    // LINEAR, REPEAT
uniform vec2 texture_shift;           // o_k, texels
uniform int copy;                     // k

layout(location = 0) out vec4 copy_inputs;  // offset (px), texture factor

void main() {
  vec2 p = gl_FragCoord.xy;  // pixel center
  vec2 grid = vec2(textureSize(offset_grids, 0).xy);
  vec2 tex = vec2(textureSize(contour_texture, 0));
  vec2 offset = texture(offset_grids, vec3((p / float(contour.grid_cell) + 0.5) / grid, float(copy))).xy;
  float t_k = 1.0 - texture(contour_texture, (p / contour.texture_scale + texture_shift) / tex).r;
  copy_inputs = vec4(offset, 1.0 + (t_k - 1.0) * contour.texture_strength, 0.0);
}
