// The silhouette paths as window paths on the GPU (Kalnins et al. 2002, §4.5): the twin of
// common/strokes/strokes.cpp window_lines for the silhouettes (PathBuilder::add and flush),
// in double (shaders/strokes/silhouette_rows.comp): each path's first piece of two points or
// more in front of the near plane, its window arc lengths, its row and its points' rows,
// written into the frame's path table after the creases' and borders'
// (gpu/strokes/crease_rows.hpp) and placed by prefix sums; and the bounds the CPU sizes the
// visibility and stroke buffers by (common/strokes/visibility.hpp first_round_bound,
// length_in_margin), summed on the GPU (gpu/strokes/row_counts.hpp). Nothing is read back.
#pragma once

#include <cstddef>
#include <cstdint>

#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/silhouette_points.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

// The frame's numbers the GPU's rows follow: the window, the near plane and strokes.vis_step_px.
struct RowFrame {
  int width = 0, height = 0;
  float near = 0, step_px = 0;
};

class SilhouetteRows {
 public:
  // For a scene of `records` face records (the most silhouette paths, half their most points).
  explicit SilhouetteRows(size_t records);
  // Writes the paths of the silhouette_paths table `paths`, their points where `points`
  // placed them, into `table` after the creases' and borders' rows (their counts in
  // `counts`, gpu/strokes/row_counts.hpp, where these go too), their points from
  // `first_point`.
  void operator()(const Texture& paths, const SilhouettePoints& points, const RowFrame& frame, uint32_t first_point,
                  const Buffer& counts, const UploadedPaths& table);

 private:
  void bind(const Texture& paths, const SilhouettePoints& points, const Buffer& counts,
            const UploadedPaths& table) const;

  Program args_, pieces_step_, rows_step_, totals_;
  ExclusiveScan scan_;
  size_t records_ = 0;
  Buffer pieces_, kept_, entries_;
};

}  // namespace plumbago::gpu
