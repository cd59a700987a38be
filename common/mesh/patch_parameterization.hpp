// A (u, v) for a mesh that has none, on the disk-like patch around some of its faces: CGAL's
// least-squares conformal map (Lévy et al. 2002, CGAL::Surface_mesh_parameterization
// LSCM_parameterizer_3), the patch's longest border free. Kalnins et al. 2002, §6.3, move
// mobile hatching along u-lines of a "smooth surface region with roughly uniform
// uv-parameterization": this is that region where the mesh brings none.
//
// The patch: the faces reached from `seeds` across shared edges (common/mesh/mesh_topology.hpp,
// which splits non-manifold faces off) whose centroid lies within `radius` of the seeds' mean
// centroid. It must be a topological disk (one border, Euler characteristic 1, manifold); where it is not, the radius
// is halved, up to 4 times. The map's rotation and scale are CGAL's; it is turned so that the object-space direction
// `along` at the seeds runs along +u, and scaled so that u and v are lengths (object units).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago {

// Per face corner (3 f + k), the patch's (u, v); NaN for the faces outside it. Throws
// std::runtime_error saying why when no disk-like patch is found or CGAL's solver fails.
std::vector<glm::vec2> patch_uvs(const Mesh& mesh, const std::vector<uint32_t>& seeds, double radius, glm::dvec3 along);

}  // namespace plumbago
