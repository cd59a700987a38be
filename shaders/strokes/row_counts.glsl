// What the GPU's window-path steps count (gpu/strokes/row_counts.hpp RowCounts, std430), at
// binding 0: the indirect dispatch over the silhouette paths, the rows each step wrote and
// their entries, and 64-bit sums (low, high) per line style (crease 0, border 1, silhouette
// 2, decal d 3 + d) of the pieces' first-round samples, most runs, their most length and
// most points.
layout(std430, binding = 0) buffer Counts {
  uvec4 silhouette_args;  // (groups x, y, 1, silhouette paths)
  uint crease_rows, crease_entries, silhouette_base, silhouette_rows;
  uint silhouette_entries, decal_rows, decal_entries, counts_pad;
  uint sums[];  // 8 per style
};
