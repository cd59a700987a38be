// What the GPU's window-path steps count (gpu/strokes/row_counts.hpp RowCounts, std430), at
// binding 0: the indirect dispatch over the silhouette paths, 64-bit sums (low, high) per line
// style (crease 0, border 1, silhouette 2) of the pieces' first-round samples, most runs,
// their most length and most points, and the rows each step wrote and their entries.
layout(std430, binding = 0) buffer Counts {
  uvec4 silhouette_args;  // (groups x, y, 1, silhouette paths)
  uint sums[24];
  uint crease_rows, crease_entries, silhouette_base, silhouette_rows;
  uint silhouette_entries, counts_pad0, counts_pad1, counts_pad2;
};
