// Decals and hatches as window paths on the GPU (Kalnins et al. 2002, §3, §6): the twin of
// common/strokes/strokes.cpp window_lines for the surface strokes (PathBuilder::add_decal and
// flush), in double (shaders/strokes/decal_rows.comp): each point placed in the world and the
// window, with its face's key and its pressure, each stroke cut where a point missed the
// surface (or lies off its hatch's object), where the object changes and at the near plane,
// its pieces' arc lengths, rows and points' rows written in the frame's path table after the
// silhouettes' and placed by prefix sums; and their bounds summed per decal
// (gpu/strokes/row_counts.hpp). The strokes' points go up once, in object space; a mobile
// hatch's copies (common/strokes/mobile_hatching.hpp, placed on the CPU) each frame with the
// strokes drawn and their weights. Nothing is read back.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/strokes/strokes.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/strokes/piece_rows.hpp"
#include "gpu/strokes/silhouette_rows.hpp"
#include "gpu/strokes/window_paths.hpp"

namespace plumbago::gpu {

class DecalRows {
 public:
  // Uploads the points of `decals` (kept as long as this) on `scene`'s objects.
  DecalRows(const Scene& scene, const DecalSurface& decals);
  // The points of the strokes `drawn` this frame: at most as many pieces.
  static size_t points(const SurfaceStrokes& drawn);
  // Writes the rows of the strokes `drawn` (of this DecalSurface) after the silhouettes' in
  // `table`, their points from `first_point`, and their counts, entries and bounds to
  // `counts` (gpu/strokes/row_counts.hpp).
  void operator()(const Scene& scene, const SurfaceStrokes& drawn, const RowFrame& frame, uint32_t first_point,
                  const Buffer& counts, const UploadedPaths& table);

 private:
  void place_points(const Scene& scene, const SurfaceStrokes& drawn, const RowFrame& frame);

  Program points_step_;
  PieceRows rows_;
  const DecalSurface& decals_;
  std::vector<uint32_t> first_record_, first_key_;  // per decal; per object
  Buffer fixed_, strokes_buffer_;                   // the strokes' points; this frame's strokes
  ScratchBuffer scratch_;
  size_t strokes_ = 0;  // drawn this frame
};

}  // namespace plumbago::gpu
