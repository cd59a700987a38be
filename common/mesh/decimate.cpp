// Edge collapse with quadric error metrics: see common/mesh/decimate.hpp.
#include "common/mesh/decimate.hpp"

// GCC 12 at -O3 reads Eigen's fixed 4 x 4 quadrics in CGAL's Garland-Heckbert policies as
// maybe uninitialized (Eigen initializes them; a known false positive of that warning).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <numeric>
#include <string>
#include <vector>

#include "common/mesh/cgal_surface_mesh.hpp"

namespace plumbago {
namespace {

using Kernel = CgalKernel;
using SurfaceMesh = CgalMesh;
namespace SMS = CGAL::Surface_mesh_simplification;

SurfaceMesh surface_mesh(const Mesh& mesh) {
  SurfaceMesh out;
  std::vector<uint32_t> faces(mesh.triangles.size());
  std::iota(faces.begin(), faces.end(), 0u);
  std::unordered_map<uint32_t, SurfaceMesh::Vertex_index> vertex;
  if (std::optional<uint32_t> refused = add_faces(mesh, faces, out, vertex))
    throw MeshError(mesh.name + ": cannot be decimated: face " + std::to_string(*refused) +
                    " makes it no manifold (an edge of three faces or a vertex joining two fans)");
  return out;
}

Mesh mesh_of(const SurfaceMesh& s, const Mesh& from, size_t faces) {
  Mesh out;
  out.name = from.name + " decimated to " + std::to_string(faces) + " faces";
  out.origin = from.origin;
  std::vector<uint32_t> index(s.number_of_vertices() + s.number_of_removed_vertices(), 0);
  for (SurfaceMesh::Vertex_index v : s.vertices()) {
    index[v] = uint32_t(out.positions.size());
    const Kernel::Point_3& p = s.point(v);
    out.positions.emplace_back(float(p.x()), float(p.y()), float(p.z()));
  }
  for (SurfaceMesh::Face_index f : s.faces()) {
    glm::uvec3 t;
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(s.halfedge(f), s)) t[k++] = index[v];
    out.triangles.push_back(t);
  }
  weld_vertices(out);
  compute_normals(out);
  return out;
}

}  // namespace

Mesh decimate(const Mesh& mesh, size_t faces) {
  if (faces < kMinDecimatedFaces)
    throw MeshError(mesh.name + ": cannot be decimated to " + std::to_string(faces) + " faces (at least " +
                    std::to_string(kMinDecimatedFaces) + ")");
  if (mesh.triangles.size() <= faces) return mesh;
  SurfaceMesh s = surface_mesh(mesh);
  SMS::GarlandHeckbert_plane_policies<SurfaceMesh, Kernel> quadrics(s);
  SMS::Count_stop_predicate<SurfaceMesh> stop(3 * faces / 2);
  SMS::edge_collapse(s, stop, CGAL::parameters::get_cost(quadrics.get_cost()).get_placement(quadrics.get_placement()));
  return mesh_of(s, mesh, faces);
}

}  // namespace plumbago
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
