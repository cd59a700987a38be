// What the GPU's window-path steps count (shaders/strokes/row_counts.glsl Counts, std430): the
// creases' and borders' rows and entries (gpu/strokes/crease_rows.hpp), the silhouettes'
// (gpu/strokes/silhouette_rows.hpp), the decals' and hatches' (gpu/strokes/decal_rows.hpp),
// and per line style the bounds the CPU sizes the visibility and stroke buffers by, summed.
// The GPU completes the path table from them (TableRows); a frame that sizes its buffers
// reads them back, 48 bytes and 32 a line style.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

struct RowCountsHeader {
  glm::uvec4 silhouette_args;  // the groups over the silhouette paths, and their count
  uint32_t crease_rows, crease_entries, silhouette_base, silhouette_rows;
  uint32_t silhouette_entries, decal_rows, decal_entries, pad;
};
static_assert(sizeof(RowCountsHeader) == 48, "std430 layout of row_counts.glsl Counts");

struct RowCounts : RowCountsHeader {
  std::vector<uint32_t> sums;  // 64-bit (low, high), per style: first-round samples, runs, run length, points

  // The bytes of the counts of `styles` line styles (3 and one per decal).
  static size_t bytes(size_t styles) { return sizeof(RowCountsHeader) + styles * 8 * sizeof(uint32_t); }
  // Style s's (PathTable::style_of) sum v.
  double sum(size_t style, int v) const {
    const size_t i = 2 * (4 * style + size_t(v));
    return double(sums[i]) + 4294967296.0 * double(sums[i + 1]);
  }
  // Reads them from `buffer` (of bytes(styles)), once the steps have run.
  static RowCounts read(const Buffer& buffer, size_t styles);
  // Adds the GPU's paths' bounds to `table`.
  void add_bounds_to(UploadedPaths& table) const;
};

// Completes a path table the GPU wrote, as `counts` (RowCounts) counts its rows: its header
// (shaders/strokes/table_rows.comp).
class TableRows {
 public:
  TableRows();
  void operator()(const Buffer& counts, const UploadedPaths& table) const;

 private:
  Program header_;
};

}  // namespace plumbago::gpu
