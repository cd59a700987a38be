#version 450 core
// A stroke fragment (Kalnins et al. 2002, §4.1): the ribbon's alpha times its stroke texture, through the
// paper's alpha transfer (Kalnins et al. 2002, §4.4), premultiplied for the ONE, ONE_MINUS_SRC_ALPHA blend.
// Formula in common/strokes/stroke.hpp and common/strokes/stroke_paper.hpp.
#include "util/common_wrap.glsl"

uniform sampler2DArray stroke_textures;  // u REPEAT, v CLAMP_TO_EDGE, LINEAR
uniform sampler2D paper_height;          // read texel for pixel, wrapping
noperspective in vec2 uv;
noperspective in float alpha;
flat in vec3 color;
flat in float layer;
layout(location = 0) out vec4 premultiplied;

float sat(float v) { return clamp(v, 0.0, 1.0); }

void main() {
  ivec2 x = ivec2(gl_FragCoord.xy);
  float a = alpha * texture(stroke_textures, vec3(uv, layer)).r;
  float h = texelFetch(paper_height, wrapped_texel(x, textureSize(paper_height, 0)), 0).r;
  float h_adjusted = sat(2.0 * stroke_paper.contrast * (sat(2.0 * stroke_paper.brightness * h) - 0.5) + 0.5);
  float a_paper = h_adjusted * sat(2.0 * a) + (1.0 - h_adjusted) * sat(2.0 * a - 1.0);
  premultiplied = vec4(color * a_paper, a_paper);
}
