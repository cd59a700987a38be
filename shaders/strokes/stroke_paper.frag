#version 450 core
// The paper effect of stroke-based rendering (Kalnins et al. 2002, §4.4): at the stroke objects' pixels,
// the coat onto the white page through the paper's alpha transfer; every other pixel is
// left as the other pipelines drew it. Formula in common/strokes/stroke_paper.hpp.
#include "util/common_wrap.glsl"

uniform usampler2D ids;          // G-buffer: object id, triangle index
uniform sampler2D coat;          // straight alpha
uniform sampler2D sprite_depth;  // the sketchy sprite's depth, 1 where it drew nothing
uniform sampler2D paper_height;  // read texel for pixel, wrapping
uniform bool has_coat, has_sprite;
layout(std430, binding = 0) readonly buffer StrokeObjects { uint stroke_object[]; };  // per G-buffer object

layout(location = 0) out vec4 color;

float sat(float v) { return clamp(v, 0.0, 1.0); }

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  uint object = texelFetch(ids, x, 0).x;
  if (object == 0u || stroke_object[object - 1u] == 0u || (has_sprite && texelFetch(sprite_depth, x, 0).r < 1.0))
    discard;
  vec4 layer = has_coat ? texelFetch(coat, x, 0) : vec4(0.0);
  float h = texelFetch(paper_height, wrapped_texel(x, textureSize(paper_height, 0)), 0).r;
  float h_adjusted = sat(2.0 * stroke_paper.contrast * (sat(2.0 * stroke_paper.brightness * h) - 0.5) + 0.5);
  float a = h_adjusted * sat(2.0 * layer.a) + (1.0 - h_adjusted) * sat(2.0 * layer.a - 1.0);
  color = vec4(layer.rgb * a + vec3(1.0 - a), 1.0);
}
