#version 450 core
// The paper effect of stroke-based rendering (SPEC 4.2): the coat onto the white page
// through the paper's alpha transfer. Formula in common/stroke_paper.hpp.
#include "common_wrap.glsl"

uniform sampler2D coat;          // straight alpha
uniform sampler2D paper_height;  // read texel for pixel, wrapping

layout(location = 0) out vec4 color;

float sat(float v) { return clamp(v, 0.0, 1.0); }

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  vec4 layer = texelFetch(coat, x, 0);
  float h = texelFetch(paper_height, wrapped_texel(x, textureSize(paper_height, 0)), 0).r;
  float h_adjusted = sat(2.0 * stroke_paper.contrast * (sat(2.0 * stroke_paper.brightness * h) - 0.5) + 0.5);
  float a = h_adjusted * sat(2.0 * layer.a) + (1.0 - h_adjusted) * sat(2.0 * layer.a - 1.0);
  color = vec4(layer.rgb * a + vec3(1.0 - a), 1.0);
}
