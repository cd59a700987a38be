// What the GPU's window-path steps count (shaders/strokes/row_counts.glsl Counts, std430): the
// creases' and borders' rows and entries (gpu/strokes/crease_rows.hpp), the silhouettes'
// (gpu/strokes/silhouette_rows.hpp), and per line style the bounds the CPU sizes the
// visibility and stroke buffers by, summed. The GPU completes the path table from them
// (TableRows); a frame that sizes its buffers reads them back, 144 bytes.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

struct RowCounts {
  glm::uvec4 silhouette_args;  // the groups over the silhouette paths, and their count
  uint32_t sums[24];           // 64-bit (low, high), per style: first-round samples, runs, run length, points
  uint32_t crease_rows, crease_entries, silhouette_base, silhouette_rows;
  uint32_t silhouette_entries, pad[3];

  // Style s's (crease 0, border 1, silhouette 2) sum v.
  double sum(int style, int v) const {
    const int i = 2 * (4 * style + v);
    return double(sums[i]) + 4294967296.0 * double(sums[i + 1]);
  }
  // Reads them from `buffer`, once the steps have run.
  static RowCounts read(const Buffer& buffer);
  // Adds the GPU's paths' bounds to `table`.
  void add_bounds_to(UploadedPaths& table) const;
};
static_assert(sizeof(RowCounts) == 144, "std430 layout of row_counts.glsl Counts");

// Completes a path table whose first rows the GPU wrote, as `counts` (RowCounts) counts them:
// the CPU's rows after them, and the header (shaders/strokes/table_rows.comp).
class TableRows {
 public:
  TableRows();
  void operator()(const Buffer& counts, const UploadedPaths& table) const;

 private:
  Program place_, header_;
};

}  // namespace plumbago::gpu
