// Principal curvature per vertex (Lee §5.3; Pacheco §6; Alliez et al. 2003).
//
// Sign convention: k > 0 where the surface bends away from its normal (a sphere with
// outward normals has k_min = k_max = 1/R), k < 0 where it bends towards it.
//
// `tensor` (Cohen-Steiner & Morvan 2003, as used by Alliez et al. 2003):
//   T(v) = 1/|B| sum_{e in B} beta(e) |e ∩ B| ê êᵀ
// over B, the part of the surface within distance r of v that is connected to v
// (the connected component of surface ∩ ball(v, r) holding v; to second order in r the
// geodesic ball). |e ∩ B| is the exact length of the clipped edge, |B| the exact area of
// the clipped triangles (triangle ∩ disk in each triangle's plane). beta(e) is the
// signed dihedral angle, > 0 on convex edges, from atan2. The eigenvector of the
// *larger* eigenvalue is the direction of *minimum* curvature (Cohen-Steiner & Morvan:
// an edge bends the surface across itself), so k_max = larger eigenvalue with d_min its
// eigenvector, k_min = smaller eigenvalue with d_max its eigenvector.
// r = radius x bbox diagonal; radius = 0 is the 1-ring: B = the faces around v, the
// edges at v counted whole and the edges opposite v counted half (each face lies in
// three 1-rings and each edge in two as a spoke and two as an opposite edge, so this
// weighting counts the tensor as often as the area).
//
// Readings (docs/curvature.md):
//  - `normal = ball` (default): n = area-weighted face normal over B and T restricted to
//    n's tangent plane. The literal reading (Alliez et al. 2003), `normal = tensor`, takes the eigenvector
//    of the smallest-magnitude eigenvalue; wherever k_min ~ 0 (a cylinder, the torus's
//    top and bottom circles) two eigenvalues are ~0 and that choice is arbitrary, so
//    there the ball normal is projected into their eigenspace.
//  - `ring_fallback = true` (default): where the ball does not reach all of v's
//    neighbors, the 1-ring is used. The tensor lives on edges, so a ball that cuts the
//    edges at v short of their far ends overestimates |k| by about (edge length / r).
//    The literal ball (Alliez et al. 2003) is `false`.
//
// `jet`: Monge jet fitting (Cazals & Pouget 2005) of degree `jet_degree` on the
// `jet_rings`-ring of v (grown until it has twice as many points as the polynomial has
// coefficients), with the Monge normal made to agree with the mesh's orientation.
// `jet_solver = eigen` (default) fits it with Eigen (normal equations of the same
// preconditioned least squares, common/curvature/curvature_jet_eigen.cpp); `cgal` runs CGAL's
// Monge_via_jet_fitting (SVD), the checked reference (tests/curvature/curvature_jet_test.cpp).
//
// `auto` (default): the tensor, unless more than `auto_fold_share` (0.03%) of the faces
// are folded over (a face whose normal is more than 90 degrees from one of its corners'
// area-weighted normals), then the jet. The tensor sums dihedral angles, which on a
// smooth surface are about k x edge length (1 degree at the default density); a folded
// face adds two of about 180 degrees, whatever the ball's size. On tori, spheres and
// saddles jittered by up to 0.45 of a cell, the share of vertices more than 50% off
// follows the share of folded faces: 1.1% folded faces, 24% vertices off (torus); 0.1%,
// 2.5%; 0.02%, 0.3%. The jet reads only positions and stays within 0.2% off
// (docs/curvature.md).
//
// Umbilic and flat vertices (Lee §5.3): where |k_max - k_min| < umbilic_ratio
// (|k_max| + |k_min|) + flat_curvature / bbox diagonal, d_min is propagated from the
// neighbors (curvature_directions.cpp), then smoothed: `direction_smoothing` sweeps
// replace each d_min not held fixed by the mean line of its own, its neighbors' and,
// weighted by its firmness, its estimate. Firmness is 0 where the directions are
// undefined and rises linearly to 1 (held fixed) where |k_max - k_min| reaches
// `direction_firm` x the umbilic test's threshold, so weakly anisotropic vertices, whose
// directions are mostly noise, follow their firmer neighbors. 0 sweeps: Lee's
// propagation alone, where fronts from different sides meet in seams.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "common/core/stage.hpp"
#include "common/mesh/mesh.hpp"

namespace plumbago {

enum class CurvatureMethod { Auto, Tensor, Jet };
enum class CurvatureNormal { Ball, Tensor };
enum class JetSolver { Eigen, Cgal };
enum class BallClip { Exact, Approximate };

struct CurvatureParams {
  static constexpr const char* stage = "curvature";
  CurvatureMethod method;
  float auto_fold_share;
  float radius;
  CurvatureNormal normal;
  bool ring_fallback;
  BallClip ball_clip;
  int jet_degree, jet_rings;
  JetSolver jet_solver;
  float umbilic_ratio, flat_curvature;
  int direction_smoothing;
  float direction_firm;
  template <class V>
  void visit(V& v) {
    v.choice(method, "method", CurvatureMethod::Auto, {"auto", "tensor", "jet"},
             "estimator: Cohen-Steiner/Morvan tensor (the paper's), jet fitting, or auto: the tensor unless more "
             "than auto_fold_share of the faces are folded, then the jet");
    v.real(auto_fold_share, "auto_fold_share", 0.0003, 0.0, 1.0,
           "auto: the share of folded faces (normal > 90 deg from a corner's normal) above which the jet is used");
    v.real(radius, "radius", 0.01, 0.0, 0.5,
           "tensor: geodesic ball radius x bbox diagonal (Pacheco: 0.01); 0 = the 1-ring");
    v.choice(normal, "normal", CurvatureNormal::Ball, {"ball", "tensor"},
             "tensor: normal from the ball's faces, or the tensor's smallest eigenvector (Alliez et al. 2003)");
    v.boolean(ring_fallback, "ring_fallback", true,
              "tensor: the 1-ring where the ball misses some of v's neighbors (false: the literal ball)");
    v.choice(ball_clip, "ball_clip", BallClip::Exact, {"exact", "approximate"},
             "tensor: faces and edges cut by the ball clipped exactly, or weighted by (r - d_min) / (d_max - d_min) "
             "over their corners and middle (CGAL 6's interpolated corrected curvatures)");
    v.integer(jet_degree, "jet_degree", 2, 2, 4, "jet: degree of the fitted polynomial");
    v.integer(jet_rings, "jet_rings", 2, 1, 8, "jet: rings of neighbors fitted (more if too few points)");
    v.choice(jet_solver, "jet_solver", JetSolver::Eigen, {"eigen", "cgal"},
             "jet: the least-squares fit by Eigen's normal equations, or CGAL's Monge_via_jet_fitting (the reference)");
    v.real(umbilic_ratio, "umbilic_ratio", 0.1, 0.0, 1.0,
           "directions propagated where |k_max - k_min| < this x (|k_max| + |k_min|) + flat");
    v.real(flat_curvature, "flat_curvature", 0.05, 0.0, 1.0,
           "the + flat term of the umbilic test, x 1 / bbox diagonal");
    v.integer(direction_smoothing, "direction_smoothing", 30, 0, 10000,
              "sweeps smoothing the propagated and weakly defined directions (0: Lee's propagation only)");
    v.real(direction_firm, "direction_firm", 3.0, 1.0, 100.0,
           "directions are held fixed where |k_max - k_min| is this many times the umbilic threshold, "
           "and held less firmly below");
  }
};

// Per vertex: unit normal agreeing with the mesh orientation, k_min <= k_max, unit
// directions tangent to the normal and orthogonal to each other. Never NaN.
struct Curvature {
  std::vector<float> k_min, k_max;
  std::vector<glm::vec3> normal, d_min, d_max;
  size_t size() const { return k_min.size(); }
};

struct CurvatureOptions {
  bool use_cache = true;  // read and write the on-disk cache (curvature_cache.hpp)
  std::string cache_dir;  // empty: curvature_cache_dir()
  bool progress = true;   // show progress on stderr when a computation runs long
};

// Cached: keyed by the mesh content, the method and every parameter. A stale or corrupt
// cache file is reported on stderr (unless !progress) and recomputed.
Curvature compute_curvature(const Mesh& mesh, const CurvatureParams& params, const CurvatureOptions& options = {});

// How firmly a vertex's estimated direction holds while the field is smoothed: 0 where
// it is undefined (the umbilic/flat test: propagated from the neighbors), rising linearly
// to 1 at `direction_firm` times the test's threshold, 1 beyond (held fixed).
double direction_firmness(float k_min, float k_max, const CurvatureParams& p, float bbox_diagonal);

// The estimator `method = auto` picks for this mesh (tensor or jet); the others as given.
CurvatureMethod resolved_method(const Mesh& mesh, const CurvatureParams& params);
const char* method_name(CurvatureMethod method);

// The share of faces folded over: whose normal is more than 90 degrees from the
// area-weighted normal of one of their corners (0 for a mesh without faces).
double folded_face_share(const Mesh& mesh);

// The computation itself, no cache.
Curvature estimate_curvature(const Mesh& mesh, const CurvatureParams& params, bool progress = false);

// One per object the G-buffer draws (common/sketchy/sketchy.hpp ordinary_objects).
inline constexpr Slot<std::vector<Curvature>> kCurvature{"curvature.principal"};

struct Scene;
struct Preprocessed;
struct CurvatureStage {
  using Params = TypeList<CurvatureParams>;
  static void make(const Scene& scene, Preprocessed& out);
  static StageDesc describe() {
    return {.name = "curvature",
            .kind = StageKind::Preprocessing,
            .doc = "principal curvature per vertex (Lee et al. 2006, §5.3; Alliez et al. 2003)",
            .params = {"curvature"},
            .outputs = {{.handle = kCurvature,
                         .channels = 8,
                         .texel = Texel::Host,
                         .doc = "k_min, k_max and their directions, per vertex of each object"}},
            .preprocess = make};
  }
};

}  // namespace plumbago
