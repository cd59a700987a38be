// A disk-like patch's (u, v) by CGAL's LSCM: see common/mesh/patch_parameterization.hpp.
#include "common/mesh/patch_parameterization.hpp"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

#include "common/mesh/cgal_surface_mesh.hpp"
#include "common/mesh/mesh_topology.hpp"

namespace plumbago {
namespace {

using Kernel = CgalKernel;
using SurfaceMesh = CgalMesh;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

glm::dvec3 centroid(const Mesh& mesh, uint32_t f) {
  glm::dvec3 sum(0.0);
  for (int k = 0; k < 3; ++k) sum += glm::dvec3(mesh.positions[mesh.triangles[f][k]]);
  return sum / 3.0;
}

// The faces reached from `seeds` across shared edges (common/mesh/mesh_topology.hpp) with
// their centroid within `radius` of the seeds' mean centroid.
std::vector<uint32_t> patch_faces(const Mesh& mesh, const MeshTopology& topology, const std::vector<uint32_t>& seeds,
                                  double radius) {
  glm::dvec3 center(0.0);
  for (uint32_t f : seeds) center += centroid(mesh, f) / double(seeds.size());
  std::vector<uint8_t> in(mesh.triangles.size(), 0);
  std::vector<uint32_t> out, todo;
  for (uint32_t f : seeds)
    if (!in[f]) in[f] = 1, todo.push_back(f);
  while (!todo.empty()) {
    uint32_t f = todo.back();
    todo.pop_back();
    out.push_back(f);
    for (uint32_t e : topology.face_edges[f])
      for (int32_t g : topology.edges[e].face)
        if (g >= 0 && !in[size_t(g)] && glm::distance(centroid(mesh, uint32_t(g)), center) <= radius)
          in[size_t(g)] = 1, todo.push_back(uint32_t(g));
  }
  return out;
}

// `faces` as a CGAL mesh, `vertex` mapping the mesh's vertices to its own; false where it
// is no topological disk (a non-manifold face, not one border, Euler characteristic not 1).
bool disk_mesh(const Mesh& mesh, const std::vector<uint32_t>& faces, SurfaceMesh& sm,
               std::unordered_map<uint32_t, SurfaceMesh::Vertex_index>& vertex) {
  if (add_faces(mesh, faces, sm, vertex)) return false;
  std::vector<SurfaceMesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(sm, std::back_inserter(borders));
  const long euler = long(sm.number_of_vertices()) - long(sm.number_of_edges()) + long(sm.number_of_faces());
  return borders.size() == 1 && euler == 1;
}

// The rotation and scale that take the map at face `f` (corners `q`, their points `p`) to
// one whose +u runs along `along` and whose lengths are the surface's.
glm::dmat2 frame_at(const glm::dvec3 p[3], const glm::dvec2 q[3], glm::dvec3 along) {
  glm::dmat2 Q(q[1] - q[0], q[2] - q[0]);
  if (std::abs(glm::determinant(Q)) < 1e-300) return glm::dmat2(1.0);
  glm::dmat2 inverse = glm::inverse(Q);
  glm::dvec3 ju = (p[1] - p[0]) * inverse[0][0] + (p[2] - p[0]) * inverse[0][1];  // d point / d u
  glm::dvec3 jv = (p[1] - p[0]) * inverse[1][0] + (p[2] - p[0]) * inverse[1][1];  // d point / d v
  glm::dmat2 jtj(glm::dot(ju, ju), glm::dot(ju, jv), glm::dot(ju, jv), glm::dot(jv, jv));
  glm::dvec2 w = glm::inverse(jtj) * glm::dvec2(glm::dot(ju, along), glm::dot(jv, along));  // along in (u, v)
  const double angle = std::atan2(w.y, w.x), scale = std::sqrt((jtj[0][0] + jtj[1][1]) / 2);
  const double c = std::cos(-angle) * scale, s = std::sin(-angle) * scale;
  return glm::dmat2(c, s, -s, c);
}

}  // namespace

std::vector<glm::vec2> patch_uvs(const Mesh& mesh, const std::vector<uint32_t>& seeds, double radius,
                                 glm::dvec3 along) {
  if (seeds.empty()) throw std::runtime_error("no faces to parameterize around");
  const MeshTopology topology = build_topology(mesh);
  for (int attempt = 0; attempt < 5; ++attempt, radius /= 2) {
    const std::vector<uint32_t> faces = patch_faces(mesh, topology, seeds, radius);
    SurfaceMesh sm;
    std::unordered_map<uint32_t, SurfaceMesh::Vertex_index> vertex;
    if (!disk_mesh(mesh, faces, sm, vertex)) continue;
    auto uv = sm.add_property_map<SurfaceMesh::Vertex_index, Kernel::Point_2>("v:uv").first;
    SMP::Error_code error =
        SMP::parameterize(sm, SMP::LSCM_parameterizer_3<SurfaceMesh>(), PMP::longest_border(sm).first, uv);
    if (error != SMP::OK) throw std::runtime_error(std::string("CGAL's LSCM: ") + SMP::get_error_message(error));
    auto corner = [&](uint32_t f, int k) {
      Kernel::Point_2 t = uv[vertex.at(mesh.triangles[f][k])];
      return glm::dvec2(t.x(), t.y());
    };
    glm::dvec3 p[3];
    glm::dvec2 q[3];
    for (int k = 0; k < 3; ++k)
      p[k] = glm::dvec3(mesh.positions[mesh.triangles[seeds[0]][k]]), q[k] = corner(seeds[0], k);
    const glm::dmat2 frame = frame_at(p, q, along);
    std::vector<glm::vec2> out(3 * mesh.triangles.size(), glm::vec2(std::numeric_limits<float>::quiet_NaN()));
    for (uint32_t f : faces)
      for (int k = 0; k < 3; ++k) out[3 * size_t(f) + size_t(k)] = glm::vec2(frame * corner(f, k));
    return out;
  }
  throw std::runtime_error("no disk-like patch around the faces (one border, no handle) within radius " +
                           std::to_string(radius * 32));
}

}  // namespace plumbago
