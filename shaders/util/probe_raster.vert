#version 450 core
// Limit probes (gpu/core/limits.hpp): the scene's triangles, clip-space positions pulled
// from a buffer, with nothing else computed.
layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };

void main() { gl_Position = positions[gl_VertexID]; }
