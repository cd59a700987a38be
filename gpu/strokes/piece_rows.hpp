// The steps a window-path maker runs once its points are placed (gpu/strokes/crease_rows.hpp,
// decal_rows.hpp; one program each of its shader): per source path, its pieces, their entries
// and bounds (STEP_PIECES); the prefix sums of both; per source path, its pieces' rows and
// their points' rows (STEP_ROWS); and its totals in the counts (STEP_TOTALS). The shader's
// buffers: the counts at 0 (gpu/strokes/row_counts.hpp), its own two at 1 and 2, the pieces'
// and entries' sums at 3 and 4, the path table at 6 and 7; its uniforms: near, width, height,
// step_px, source_count and first_point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/silhouette_rows.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

class PieceRows {
 public:
  explicit PieceRows(const std::string& shader);  // under the shader folder
  // Sets uint uniform `name` of every step.
  void set(const char* name, uint32_t value) const;
  // Runs the steps over `sources` source paths, their points from `first_point` in `table`;
  // `own`: the shader's buffers at bindings 1 and 2.
  void operator()(const RowFrame& frame, size_t sources, uint32_t first_point, const Buffer& counts,
                  const UploadedPaths& table, const Buffer* const (&own)[2]);

 private:
  Program pieces_step_, rows_step_, totals_;
  ExclusiveScan scan_;
  ScratchBuffer pieces_, entries_;
};

// A dispatch of `step` over `count` rows, one invocation each (util/rows.glsl row_index).
void over_rows(const Program& step, size_t count);

}  // namespace plumbago::gpu
