// The silhouette paths as window paths on the GPU (Kalnins et al. 2002, §4.5): the twin of
// common/strokes/strokes.cpp window_lines for the silhouettes (PathBuilder::add and flush),
// in double (shaders/strokes/silhouette_rows.comp): each path's first piece of two points or
// more in front of the near plane, its window arc lengths, its row and its points' rows,
// written into the frame's path table after the CPU's paths and placed by prefix sums; and
// the bounds the CPU sizes the visibility and stroke buffers by (common/strokes/visibility.hpp
// first_round_bound, length_in_margin), summed on the GPU. The CPU reads back those sums and
// two counts alone, 64 bytes a frame, and never a path's points.
#pragma once

#include <cstddef>
#include <cstdint>

#include "gpu/gl/program.hpp"
#include "gpu/gl/scan.hpp"
#include "gpu/strokes/silhouette_points.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

// The frame's numbers the rows follow: the window, the near plane, strokes.vis_step_px, and
// the first silhouette key less its start record (common/strokes/strokes.hpp WindowLines).
struct SilhouetteRowFrame {
  int width = 0, height = 0;
  float near = 0, step_px = 0;
  uint32_t silhouette_base = 0;
};

class SilhouetteRows {
 public:
  // For a scene of `records` face records (the most silhouette paths, half their most points).
  explicit SilhouetteRows(size_t records);
  // Writes the paths of the silhouette_paths table `paths`, their points where `points`
  // placed them, into `table` from its gpu_first path and after its CPU points (it has room
  // for `records` paths and twice as many points more), then has it put up its rows after
  // them, and sets its GPU paths' bounds.
  void operator()(const Texture& paths, const SilhouettePoints& points, const SilhouetteRowFrame& frame,
                  UploadedPaths& table);

 private:
  void bind(const Texture& paths, const SilhouettePoints& points, const UploadedPaths& table) const;

  Program args_, pieces_step_, rows_step_, totals_;
  ExclusiveScan scan_;
  size_t records_ = 0;
  Buffer counts_, pieces_, kept_, entries_;
};

}  // namespace plumbago::gpu
