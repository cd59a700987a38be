// A mesh's faces as a CGAL::Surface_mesh in double, for CGAL's algorithms on it (the LSCM
// chart of common/mesh/patch_parameterization.hpp, the edge collapse of
// common/mesh/decimate.hpp).
#pragma once

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago {

using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

// Adds faces `faces` of `mesh` to `out`, each mesh vertex once (`vertex`: the mesh's vertex
// to out's). Returns the first face CGAL refused (it would make `out` no manifold: an edge of
// three faces, a vertex joining two fans), having added those before it; none when all went in.
std::optional<uint32_t> add_faces(const Mesh& mesh, const std::vector<uint32_t>& faces, CgalMesh& out,
                                  std::unordered_map<uint32_t, CgalMesh::Vertex_index>& vertex);

}  // namespace plumbago
