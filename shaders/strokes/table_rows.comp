#version 450 core
// The frame's path table completed on the GPU (gpu/strokes/row_counts.hpp TableRows): after
// the rows the GPU wrote (its creases, borders and silhouettes, strokes/row_counts.glsl), the
// rows the CPU made (its decals and hatches, their entries after the GPU's), and the table's
// header (strokes/window_paths.glsl), so that no count comes back to the CPU.
//   STEP_PLACE:  per CPU row, copied after the GPU's, its first entry moved past theirs;
//   STEP_HEADER: one invocation: the paths, entries, first silhouette entry and dispatches.
#if defined(STEP_HEADER)
layout(local_size_x = 1) in;
#else
layout(local_size_x = 64) in;  // kRowsGroup
#endif

#define PATHS_BINDING 1
#define POINTS_BINDING 2
#include "strokes/window_paths.glsl"
#include "util/rows.glsl"
#include "strokes/row_counts.glsl"

layout(std430, binding = 3) readonly buffer CpuRows { Path cpu_rows[]; };

uniform uint cpu_paths, cpu_entries;  // the CPU's rows and their entries
uniform uint cpu_silhouette_entry;    // the CPU's creases' and borders' entries (PathTable)

#if defined(STEP_PLACE)
void main() {
  uint i = row_index();
  if (i >= cpu_paths) return;
  Path row = cpu_rows[i];
  row.first_entry += crease_entries + silhouette_entries;
  paths[crease_rows + silhouette_rows + i] = row;
}
#elif defined(STEP_HEADER)
void main() {
  path_count = crease_rows + silhouette_rows + cpu_paths;
  entry_count = crease_entries + silhouette_entries + cpu_entries;
  silhouette_entry = crease_entries + cpu_silhouette_entry;
  uvec4 e = row_groups(entry_count), p = row_groups(path_count);
  over_entries = uint[3](e.x, e.y, e.z), over_paths = uint[3](p.x, p.y, p.z);
}
#endif
