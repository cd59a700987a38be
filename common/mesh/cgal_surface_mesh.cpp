// A mesh's faces as a CGAL::Surface_mesh: see common/mesh/cgal_surface_mesh.hpp.
#include "common/mesh/cgal_surface_mesh.hpp"

namespace plumbago {

std::optional<uint32_t> add_faces(const Mesh& mesh, const std::vector<uint32_t>& faces, CgalMesh& out,
                                  std::unordered_map<uint32_t, CgalMesh::Vertex_index>& vertex) {
  for (uint32_t f : faces) {
    CgalMesh::Vertex_index v[3];
    for (int k = 0; k < 3; ++k) {
      uint32_t m = mesh.triangles[f][k];
      auto [it, added] = vertex.emplace(m, CgalMesh::Vertex_index());
      if (added) {
        glm::dvec3 p(mesh.positions[m]);
        it->second = out.add_vertex(CgalKernel::Point_3(p.x, p.y, p.z));
      }
      v[k] = it->second;
    }
    if (out.add_face(v[0], v[1], v[2]) == CgalMesh::null_face()) return f;
  }
  return std::nullopt;
}

}  // namespace plumbago
