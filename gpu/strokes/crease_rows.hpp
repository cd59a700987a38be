// Crease and border paths as window paths on the GPU (Kalnins et al. 2002, §4.5): the twin of
// common/strokes/strokes.cpp window_lines for the creases and borders (PathBuilder::add with
// their edges' faces, and flush), in double (shaders/strokes/crease_rows.comp): each point
// placed in the world and the window with the first two faces around its segment that face
// the eye, each path cut into its pieces in front of the near plane, their arc lengths, their
// rows and their points' rows, written first in the frame's path table and placed by prefix
// sums, their keys the reference's (common/strokes/strokes.cpp assign_keys); and their bounds
// summed (gpu/strokes/row_counts.hpp). Their points and the faces around their segments go
// up once (common/strokes/crease_points.hpp crease_records). Nothing is read back.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/strokes/strokes.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/strokes/piece_rows.hpp"
#include "gpu/strokes/silhouette_rows.hpp"
#include "gpu/strokes/stroke_meshes.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

class CreaseRows {
 public:
  // Uploads the creases and borders of `scene`'s stroke objects (`meshes`, from line_meshes),
  // positioned by `shared` (kept as long as this).
  CreaseRows(const Scene& scene, const LineMeshes& meshes, const StrokeMeshes& shared);
  size_t points() const { return records_; }  // the creases' and borders' points: at most as many pieces
  // Writes this frame's rows first in `table`, their points from `first_point`, and their
  // counts, entries and bounds to `counts` (gpu/strokes/row_counts.hpp).
  void operator()(const Scene& scene, const RowFrame& frame, uint32_t first_point, const Buffer& counts,
                  const UploadedPaths& table);

 private:
  void place_points(const Scene& scene, const RowFrame& frame);

  Program points_step_;
  PieceRows rows_;
  const StrokeMeshes& meshes_;
  size_t records_ = 0, paths_ = 0;
  std::vector<uint32_t> first_face_;
  Buffer records_buffer_, around_, defs_, scratch_;
};

}  // namespace plumbago::gpu
