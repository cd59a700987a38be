// Jet fitting (Cazals & Pouget 2005): the independent estimator the tensor
// is checked against. The neighborhoods are gathered here; the fit is Eigen's
// (common/curvature/curvature_jet_eigen.cpp) or CGAL 5.5's Monge_via_jet_fitting, the reference.
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED 1  // CGAL's Eigen SVD; Eigen is a dependency of plumbago_common
#endif
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "common/curvature/curvature_internal.hpp"

namespace plumbago::curvature {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using JetFitting = CGAL::Monge_via_jet_fitting<Kernel>;

// Rings of neighbors around v, first point v itself (the point the Monge form is at).
struct RingGatherer {
  std::vector<uint32_t> mark, ring;
  std::vector<glm::dvec3> points;
  uint32_t stamp = 0;
  explicit RingGatherer(size_t vertices) : mark(vertices, 0) {}

  // At least `rings` rings, more while there are fewer than `wanted` points (up to
  // `rings` + 4, or the whole connected component).
  void gather(uint32_t v, int rings, size_t wanted, const Mesh& mesh, const MeshTopology& topo) {
    if (++stamp == 0) std::fill(mark.begin(), mark.end(), 0), stamp = 1;
    points.clear();
    ring.assign(1, v);
    mark[v] = stamp;
    add_points(mesh);
    for (int level = 1; !ring.empty() && (level <= rings || (points.size() < wanted && level <= rings + 4)); ++level) {
      std::vector<uint32_t> next;
      for (uint32_t u : ring)
        for (uint32_t w : topo.neighbors_of(u))
          if (mark[w] != stamp) mark[w] = stamp, next.push_back(w);
      ring.swap(next);
      add_points(mesh);
    }
  }
  void add_points(const Mesh& mesh) {
    for (uint32_t u : ring) points.emplace_back(mesh.positions[u]);
  }
};

glm::dvec3 to_glm(const Kernel::Vector_3& v) { return {v.x(), v.y(), v.z()}; }

// CGAL's Monge form is z = 1/2 (k1 x^2 + k2 y^2) + ... along its normal, so a sphere
// with outward normal has k = -1/R there: our k is -k_CGAL, and CGAL's maximal
// direction d1 becomes our minimal one.
bool cgal_fit_vertex(const std::vector<glm::dvec3>& points, int degree, const glm::vec3& mesh_normal, JetFit& out) {
  std::vector<Kernel::Point_3> cgal_points;
  for (const glm::dvec3& p : points) cgal_points.emplace_back(p.x, p.y, p.z);
  JetFitting fitting;
  JetFitting::Monge_form monge = fitting(cgal_points.begin(), cgal_points.end(), size_t(degree), 2);
  monge.comply_wrt_given_normal(Kernel::Vector_3(mesh_normal.x, mesh_normal.y, mesh_normal.z));
  out = {to_glm(monge.normal_direction()), to_glm(monge.maximal_principal_direction()),
         to_glm(monge.minimal_principal_direction()), -monge.principal_curvatures(0), -monge.principal_curvatures(1)};
  return jet_fit_finite(out);
}

}  // namespace

Curvature jet_curvature(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress) {
  const size_t n = mesh.positions.size();
  // A fit needs as many points as coefficients; with fewer than twice as many, rounding
  // noise in the positions dominates the higher degrees.
  const size_t needed = size_t((p.jet_degree + 1) * (p.jet_degree + 2) / 2), wanted = 2 * needed;
  Curvature c;
  c.k_min.assign(n, 0), c.k_max.assign(n, 0), c.d_min.assign(n, glm::vec3(0)), c.d_max.assign(n, glm::vec3(0));
  c.normal = mesh.normals;
  tbb::enumerable_thread_specific<RingGatherer> gatherers(n);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(n), 256), [&](const tbb::blocked_range<uint32_t>& range) {
    RingGatherer& ring = gatherers.local();
    for (uint32_t v = range.begin(); v != range.end(); ++v) {
      ring.gather(v, p.jet_rings, wanted, mesh, topo);
      JetFit fit;
      auto fit_vertex = p.jet_solver == JetSolver::Cgal ? cgal_fit_vertex : eigen_fit_vertex;
      if (ring.points.size() < needed || !fit_vertex(ring.points, p.jet_degree, mesh.normals[v], fit)) continue;
      c.normal[v] = fit.normal, c.d_min[v] = fit.d_min, c.d_max[v] = fit.d_max;
      c.k_min[v] = float(fit.k_min), c.k_max[v] = float(fit.k_max);
    }
    progress.advance(range.size());
  });
  return c;
}

}  // namespace plumbago::curvature
