// Silhouette path points on the GPU (Kalnins et al. 2002, §4.5): each point the silhouette
// paths list (common/strokes/silhouette_paths.hpp) placed where g = 0 on its face's slot, in
// double, and projected to the window (shaders/strokes/silhouette_points.comp), one
// invocation per point by an indirect dispatch. The reference's formula is
// common/strokes/feature_lines.cpp edge_crossing, its projection WindowProjection
// (common/strokes/strokes.hpp). The GPU makes its window paths of them
// (gpu/strokes/silhouette_rows.hpp); a frame that keeps its lines whole reads the paths back
// with their points (common/strokes/silhouette_paths.hpp chain_paths).
#pragma once

#include <vector>

#include "common/strokes/silhouette_paths.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/program.hpp"
#include "gpu/strokes/stroke_meshes.hpp"

namespace plumbago::gpu {

class SilhouettePoints {
 public:
  // Reads `shared` (made for `scene` and `meshes`, kept as long as this) and uploads the
  // crease-aware corner normals (double) once; `meshes` from line_meshes for `scene`'s
  // stroke objects.
  SilhouettePoints(const Scene& scene, const LineMeshes& meshes, const StrokeMeshes& shared);
  // Places this frame's silhouette path points from the silhouette_paths tables `paths` and
  // `crossings`, on the GPU: points() and worlds() hold them.
  void place(const Scene& scene, const LineMeshes& meshes, const Texture& paths, const Texture& crossings,
             bool normalized);
  // The paths `place` placed, read back.
  std::vector<ChainPath> read(const Scene& scene, const LineMeshes& meshes, const Texture& paths) const;
  const Buffer& points() const { return rows_; }    // SilhouettePoint, per point of the paths in order
  const Buffer& worlds() const { return worlds_; }  // glm::dvec4, each point's world position

 private:
  Program args_, points_;
  const StrokeMeshes& meshes_;
  Buffer normals_, args_buffer_, rows_, worlds_;
};

}  // namespace plumbago::gpu
