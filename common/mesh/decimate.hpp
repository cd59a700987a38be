// A mesh simplified to about a given face count by edge collapse with Garland and Heckbert's
// quadric error metrics (SIGGRAPH 1997), CGAL's Surface_mesh_simplification: for studies on
// coarse meshes (experiments/stroke_visibility) and ablations over mesh resolution, from a
// scene's mesh {"decimate_to": N} (docs/scene-format.md).
#pragma once

#include <cstddef>

#include "common/mesh/mesh.hpp"

namespace plumbago {

inline constexpr size_t kMinDecimatedFaces = 4;            // a tetrahedron
inline constexpr size_t kMaxDecimatedFaces = 100'000'000;  // what a scene may ask for

// `mesh` with about `faces` faces (CGAL stops at 3 faces / 2 edges; a mesh with borders keeps
// a few more), or unchanged where it has no more. Welded, normals recomputed, no (u, v).
// Throws MeshError naming the mesh where it is not a manifold CGAL can collapse (an edge of
// three faces, a vertex joining two fans), or `faces` is below kMinDecimatedFaces.
Mesh decimate(const Mesh& mesh, size_t faces);

}  // namespace plumbago
