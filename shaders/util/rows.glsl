// Compute steps over rows (paths, entries, ...): dispatches of (x, y, 1) workgroups of
// kRowsGroup invocations, y > 1 where more than kMaxGroups are needed.
const uint kRowsGroup = 64u;
const uint kMaxGroups = 65535u;  // per dimension (GL_MAX_COMPUTE_WORK_GROUP_COUNT)

// The groups (x, y, 1) of a dispatch over `count` rows, and the count
// (gpu/strokes/window_paths.hpp row_groups).
uvec4 row_groups(uint count) {
  uint groups = (count + kRowsGroup - 1u) / kRowsGroup, rows = (groups + kMaxGroups - 1u) / kMaxGroups;
  return uvec4(rows == 0u ? 0u : (groups + rows - 1u) / rows, rows, 1u, count);
}

// The row of this invocation in a dispatch of (x, y, 1) groups of kRowsGroup.
uint row_index() {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * kRowsGroup + gl_LocalInvocationID.x;
}
