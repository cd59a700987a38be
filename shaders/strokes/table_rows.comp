#version 450 core
// The header of a frame's path table the GPU wrote (gpu/strokes/row_counts.hpp TableRows;
// strokes/window_paths.glsl), from what its steps counted (strokes/row_counts.glsl: the
// creases' and borders' rows, the silhouettes', the decals' and hatches'), so that no count
// comes back to the CPU: the paths, entries, first silhouette entry and dispatches.
layout(local_size_x = 1) in;

#define PATHS_BINDING 1
#define POINTS_BINDING 2  // not read
#include "strokes/window_paths.glsl"
#include "util/rows.glsl"
#include "strokes/row_counts.glsl"

void main() {
  path_count = crease_rows + silhouette_rows + decal_rows;
  entry_count = crease_entries + silhouette_entries + decal_entries;
  silhouette_entry = crease_entries;
  uvec4 e = row_groups(entry_count), p = row_groups(path_count);
  over_entries = uint[3](e.x, e.y, e.z), over_paths = uint[3](p.x, p.y, p.z);
}
