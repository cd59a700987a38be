#version 450 core
// The ID image's key as two 16-bit halves (common/id_image.hpp).
flat in uint key;
layout(location = 0) out uvec2 halves;

void main() { halves = uvec2(key >> 16, key & 0xffffu); }
