// Pieces of the curvature computation (curvature.hpp) shared by its files and tests.
#pragma once

#include "common/curvature.hpp"
#include "common/mesh_topology.hpp"
#include "common/progress.hpp"

namespace plumbago::curvature {

// beta(e): the signed angle from n0 to n1 about the edge, `along` running the way face 0
// (normal n0) runs along it; > 0 where the edge is convex. atan2 keeps it accurate near
// 0 and pi, where acos(n0.n1) loses the sign and half the digits.
double signed_dihedral_angle(const glm::dvec3& n0, const glm::dvec3& n1, const glm::dvec3& along);

// An orthonormal tangent pair (t1, t2) with t1 x t2 = n, continuous in n except at
// n.z = -1 (Duff et al. 2017, "Building an orthonormal basis, revisited").
void tangent_basis(const glm::dvec3& n, glm::dvec3& t1, glm::dvec3& t2);

// Raw per-vertex estimates before propagation. A vertex a method cannot estimate (no
// faces, too few neighbors for a jet) gets the mesh normal and k_min = k_max = 0.
Curvature tensor_curvature(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress);
Curvature jet_curvature(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress);

// SPEC §1.1's umbilic/flat test: the principal directions are undefined.
bool directions_undefined(float k_min, float k_max, const CurvatureParams& p, float bbox_diagonal);

// Gives every vertex whose directions are undefined a d_min propagated from its
// neighbors, then makes every frame exactly orthonormal (d_max = n x d_min).
void propagate_directions(const MeshTopology& topo, const CurvatureParams& p, float bbox_diagonal, Curvature& c);

}  // namespace plumbago::curvature
