#version 450 core
// Test probe for the GL-exact sampler (tests/util/sampler_test.cpp): samples a texture at
// st = gl_FragCoord.xy * scale + offset (and r likewise for a 3D texture).
uniform sampler2D image2d;
uniform sampler3D image3d;
uniform bool use_3d;
uniform vec2 scale;
uniform vec2 offset;
uniform float r_scale;
uniform float r_offset;

layout(location = 0) out vec4 color;

void main() {
  vec2 st = gl_FragCoord.xy * scale + offset;
  float r = (gl_FragCoord.x + gl_FragCoord.y) * r_scale + r_offset;
  color = use_3d ? texture(image3d, vec3(st, r)) : texture(image2d, st);
}
