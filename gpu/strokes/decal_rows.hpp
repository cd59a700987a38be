// Decals and hatches as window paths on the GPU (Kalnins et al. 2002, §3, §6): the twin of
// common/strokes/strokes.cpp window_lines for the surface strokes (PathBuilder::add_decal and
// flush), in double (shaders/strokes/decal_rows.comp): each point placed in the world and the
// window, with its face's key and its pressure, each stroke cut where a point missed the
// surface (or lies off its hatch's object), where the object changes and at the near plane,
// its pieces' arc lengths, rows and points' rows written in the frame's path table after the
// silhouettes' and placed by prefix sums; and their bounds summed per decal
// (gpu/strokes/row_counts.hpp). The strokes' points go up once, in object space, with the
// charts the mobile hatching groups travel on (common/strokes/uv_chart.hpp); each frame only
// the strokes drawn, their weights and, for a mobile hatch's copy, its placement (per group:
// common/strokes/mobile_hatching.hpp), by which the GPU moves the hatch's points itself.
// Nothing is read back.
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
  // Uploads the points of `decals` on `scene`'s objects, and the charts of `mobile` (its groups).
  DecalRows(const Scene& scene, const DecalSurface& decals, const MobileHatching& mobile);
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
  std::vector<uint32_t> first_record_, chart_, first_key_;  // per decal (its group's chart); per object
  Buffer fixed_, charts_, chart_faces_, buckets_;           // the strokes' points; the charts (uv_chart.glsl)
  Buffer strokes_buffer_;                                   // this frame's strokes
  ScratchBuffer scratch_;
  size_t strokes_ = 0;  // drawn this frame
};

}  // namespace plumbago::gpu
