// Pieces of the curvature computation (curvature.hpp) shared by its files and tests.
#pragma once

#include <cmath>
#include <functional>

#include "common/curvature/curvature.hpp"
#include "common/mesh/mesh_topology.hpp"
#include "common/util/progress.hpp"

namespace plumbago::curvature {

// Symmetric 3x3 sum of w e eᵀ.
struct SymmetricTensor {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
  void add(double w, const glm::dvec3& e) {
    xx += w * e.x * e.x, xy += w * e.x * e.y, xz += w * e.x * e.z;
    yy += w * e.y * e.y, yz += w * e.y * e.z, zz += w * e.z * e.z;
  }
  glm::dvec3 apply(const glm::dvec3& v) const {
    return {xx * v.x + xy * v.y + xz * v.z, xy * v.x + yy * v.y + yz * v.z, xz * v.x + yz * v.y + zz * v.z};
  }
};

inline glm::dvec3 unit_or_zero(const glm::dvec3& v) {
  double len = glm::length(v);
  return len > 0 && std::isfinite(len) ? v / len : glm::dvec3(0);
}

// The sums over B for one vertex: T (not yet divided by |B|), |B|, and the area-weighted
// face normal.
struct BallSums {
  SymmetricTensor tensor;
  double area = 0;
  glm::dvec3 normal{0};
  // The part of a face inside B, of area a, with the face's unit normal N / |N| (N =
  // twice the face's area-weighted normal).
  void add_face(double a, const glm::dvec3& N, double N_length) {
    area += a;
    if (N_length > 0) normal += (a / N_length) * N;
  }
  // A whole face: a = |N| / 2, so its normal term is N / 2.
  void add_whole_face(const glm::dvec3& N, double N_length) { area += 0.5 * N_length, normal += 0.5 * N; }
};

// beta(e): the signed angle from n0 to n1 (normals of any length) about the edge,
// `along` running the way face 0 (normal n0) runs along it; > 0 where the edge is convex.
// atan2 keeps it accurate near 0 and pi, where acos(n0.n1) loses the sign and half the
// digits.
double signed_dihedral_angle(const glm::dvec3& n0, const glm::dvec3& n1, const glm::dvec3& along);

// An orthonormal tangent pair (t1, t2) with t1 x t2 = n, continuous in n except at
// n.z = -1 (Duff et al. 2017, "Building an orthonormal basis, revisited").
void tangent_basis(const glm::dvec3& n, glm::dvec3& t1, glm::dvec3& t2);

// The sums over each vertex's ball (or 1-ring where radius = 0 or ring_fallback asks for it),
// handed to f(v, sums) in parallel.
void for_each_vertex_sums(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress,
                          const std::function<void(uint32_t, const BallSums&)>& f);

// Raw per-vertex estimates before propagation. A vertex a method cannot estimate (no
// faces, too few neighbors for a jet) gets the mesh normal and k_min = k_max = 0.
Curvature tensor_curvature(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress);
// One vertex's jet fit: normal (agreeing with the mesh's), principal directions and
// curvatures in our sign convention (a sphere with outward normals has k = +1/R).
struct JetFit {
  glm::dvec3 normal, d_min, d_max;
  double k_min, k_max;
};
bool jet_fit_finite(const JetFit& f);
// The fit of degree `degree` through `points` (the vertex first: the Monge form is at its
// projection), oriented by `mesh_normal`; false where it is not finite.
bool eigen_fit_vertex(const std::vector<glm::dvec3>& points, int degree, const glm::vec3& mesh_normal, JetFit& out);

Curvature jet_curvature(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress);

// The umbilic/flat test of Lee et al. 2006, §5.3: the principal directions are undefined.
bool directions_undefined(float k_min, float k_max, const CurvatureParams& p, float bbox_diagonal);

// Gives every vertex whose directions are undefined a d_min propagated from its
// neighbors, then makes every frame exactly orthonormal (d_max = n x d_min).
void propagate_directions(const MeshTopology& topo, const CurvatureParams& p, float bbox_diagonal, Curvature& c);

}  // namespace plumbago::curvature
