#version 450 core
// The ID image's sketchy faces (Kalnins et al. 2002, §4.6; common/strokes/id_image.hpp rule 1), pulled
// from the object's mesh kept on the GPU (gpu/scene/mesh_buffers.hpp): one vertex per face
// corner, key = the object's first key + the face. The near plane clips through
// gl_ClipDistance (the rasterizer's own near and far planes are off: GL_DEPTH_CLAMP), and d
// goes to the fragment perspective-correct: linear in the object, so exact on a clipped face
// too, where an affinely interpolated z = near / d would not be.
layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer Corners { uvec4 corners[]; };
uniform mat4 clip;       // object to clip space
uniform vec4 depth_row;  // object point (x, 1) to linear view depth
uniform float near;
uniform uint first_key;  // the key of the object's face 0
out float d;
flat out uint key;

void main() {
  uint face = uint(gl_VertexID) / 3u;
  vec4 x = vec4(positions[corners[face][gl_VertexID % 3]].xyz, 1.0);
  d = dot(depth_row, x);
  gl_Position = clip * x;
  gl_ClipDistance[0] = d - near;
  key = first_key + face;
}
