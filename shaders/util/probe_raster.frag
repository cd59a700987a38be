#version 450 core
// Limit probes (gpu/core/limits.hpp): one 32-bit value a fragment, the triangle's index.
out uint value;

void main() { value = uint(gl_PrimitiveID); }
