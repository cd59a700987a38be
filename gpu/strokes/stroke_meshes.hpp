// The stroke objects' meshes on the GPU for the silhouette steps (Kalnins et al. 2002, §4.5),
// uploaded once and shared: every object's object-space positions one after another, and per
// face record (common/strokes/strokes.hpp first_faces) its corners' vertices, in its
// object's numbering, with bit k of w set where the edge in slot k runs from corner k + 1 to
// corner k (FeatureLineMesh::reversed_slots). The silhouette segments make them; the
// silhouette points read them (gpu/strokes/silhouette_points.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "common/strokes/line_meshes.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace plumbago::gpu {

struct StrokeMeshes {
  StrokeMeshes(const Scene& scene, const LineMeshes& meshes);
  std::vector<uint32_t> first_vertex;  // per scene object, in positions
  Buffer positions;                    // vec4 (x, 1) per vertex, std430
  Buffer faces;                        // uvec4 per face record; 0 for an object without strokes
};
inline constexpr Shared<StrokeMeshes> kStrokeMeshes{"silhouette_segments.meshes"};

}  // namespace plumbago::gpu
