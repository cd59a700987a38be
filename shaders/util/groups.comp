#version 450 core
// The indirect dispatch over a count the GPU holds (gpu/gl/groups.hpp GroupsOver): groups of
// `group_size` invocations, at least 1 and at most 65535 (the steps loop by their grid's stride).
layout(local_size_x = 1) in;

layout(std430, binding = 0) readonly buffer Counts { uint counts[]; };
layout(std430, binding = 1) writeonly buffer Groups { uvec3 groups; };

uniform uint at, group_size;

void main() { groups = uvec3(clamp((counts[at] + group_size - 1u) / group_size, 1u, 65535u), 1u, 1u); }
