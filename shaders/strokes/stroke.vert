#version 450 core
// The stroke ribbons (shaders/strokes/common_ribbon.glsl), six vertices a sample; a corner
// whose segment draws nothing goes outside the clip volume, at one point with the other five,
// so its triangles are culled. Attributes are affine in the window.
#include "strokes/common_ribbon.glsl"

uniform vec2 window_size;
noperspective out vec2 uv;
noperspective out float alpha;
flat out vec3 color;
flat out float layer;

void main() {
  Corner c = ribbon_corner(gl_VertexID);
  color = runs[c.run].color_layer.rgb;
  layer = runs[c.run].color_layer.a;
  gl_Position = c.drawn ? vec4(c.window / window_size * 2.0 - 1.0, 0.0, 1.0) : vec4(-2.0, -2.0, 0.0, 1.0);
  uv = c.uv;
  alpha = c.alpha;
}
