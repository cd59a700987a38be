#include "common/mesh_topology.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>

namespace plumbago {
namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// OpenMesh reports every refused face on omerr(); the refusals are expected here.
class QuietOpenMesh {
 public:
  QuietOpenMesh() : was_enabled_(::omerr().is_enabled()) { ::omerr().disable(); }
  ~QuietOpenMesh() {
    if (was_enabled_) ::omerr().enable();
  }

 private:
  bool was_enabled_;
};

OmMesh::VertexHandle add_vertex(OmMesh& om, const glm::vec3& p) { return om.add_vertex(OmMesh::Point(p.x, p.y, p.z)); }

// Adds every triangle, in order, so OpenMesh face i is mesh triangle i. OpenMesh refuses
// a face that would make an edge non-manifold (a third face on an edge, or a face whose
// orientation disagrees with its neighbor's), a face at a vertex whose fan is already
// closed, and a face with a repeated corner. Such a face is attached by three new copies
// of its corners instead: it keeps its geometry and its vertex indices (through
// `mesh_vertex`), but touches the rest of the mesh only at its corners' positions, so
// its edges are boundary edges.
OmMesh build_halfedge_mesh(const Mesh& mesh, std::vector<uint32_t>& mesh_vertex, MeshTopology& topo) {
  QuietOpenMesh quiet;
  OmMesh om;
  om.reserve(mesh.positions.size(), mesh.triangles.size() * 3 / 2, mesh.triangles.size());
  for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
    add_vertex(om, mesh.positions[v]);
    mesh_vertex.push_back(v);
  }
  for (const auto& t : mesh.triangles) {
    std::array<OmMesh::VertexHandle, 3> corners{OmMesh::VertexHandle(int(t[0])), OmMesh::VertexHandle(int(t[1])),
                                                OmMesh::VertexHandle(int(t[2]))};
    auto face = om.add_face(corners[0], corners[1], corners[2]);  // no per-face heap allocation
    if (!face.is_valid()) {
      for (int k = 0; k < 3; ++k) {
        corners[k] = add_vertex(om, mesh.positions[t[k]]);
        mesh_vertex.push_back(t[k]);
      }
      face = om.add_face(corners[0], corners[1], corners[2]);
      ++topo.split_faces;
    }
    auto& edges = topo.face_edges.emplace_back();
    for (auto h : om.fh_range(face))
      for (int k = 0; k < 3; ++k)
        if (om.from_vertex_handle(h) == corners[k]) edges[k] = uint32_t(om.edge_handle(h).idx());
  }
  return om;
}

// CSR lists from (key, value) pairs, each list sorted and without repeats.
void fill_csr(size_t keys, const std::vector<std::pair<uint32_t, uint32_t>>& pairs, std::vector<uint32_t>& start,
              std::vector<uint32_t>& values) {
  std::vector<uint32_t> count(keys + 1, 0);
  for (const auto& [k, v] : pairs) ++count[k + 1];
  for (size_t k = 0; k < keys; ++k) count[k + 1] += count[k];
  std::vector<uint32_t> raw(pairs.size()), fill(count.begin(), count.end() - 1);
  for (const auto& [k, v] : pairs) raw[fill[k]++] = v;
  start.assign(keys + 1, 0);
  values.clear();
  values.reserve(raw.size());
  for (size_t k = 0; k < keys; ++k) {
    auto begin = raw.begin() + count[k], end = raw.begin() + count[k + 1];
    std::sort(begin, end);
    values.insert(values.end(), begin, std::unique(begin, end));
    start[k + 1] = uint32_t(values.size());
  }
}

}  // namespace

MeshTopology build_topology(const Mesh& mesh) {
  validate_mesh(mesh);
  MeshTopology topo;
  std::vector<uint32_t> mesh_vertex;
  topo.face_edges.reserve(mesh.triangles.size());
  OmMesh om = build_halfedge_mesh(mesh, mesh_vertex, topo);

  topo.edges.resize(om.n_edges());
  std::vector<std::pair<uint32_t, uint32_t>> neighbor_pairs;
  neighbor_pairs.reserve(2 * om.n_edges());
  for (auto e : om.edges()) {
    auto h0 = om.halfedge_handle(e, 0), h1 = om.halfedge_handle(e, 1);
    if (!om.face_handle(h0).is_valid()) std::swap(h0, h1);
    auto& edge = topo.edges[e.idx()];
    edge.from = mesh_vertex[om.from_vertex_handle(h0).idx()];
    edge.to = mesh_vertex[om.to_vertex_handle(h0).idx()];
    edge.face[0] = om.face_handle(h0).idx();
    edge.face[1] = om.face_handle(h1).is_valid() ? om.face_handle(h1).idx() : -1;
    if (edge.from == edge.to) continue;  // a split face with a repeated corner
    neighbor_pairs.emplace_back(edge.from, edge.to);
    neighbor_pairs.emplace_back(edge.to, edge.from);
  }

  std::vector<std::pair<uint32_t, uint32_t>> face_pairs;
  face_pairs.reserve(3 * mesh.triangles.size());
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) face_pairs.emplace_back(mesh.triangles[f][k], f);
  fill_csr(mesh.positions.size(), face_pairs, topo.face_start_, topo.vertex_faces_);
  fill_csr(mesh.positions.size(), neighbor_pairs, topo.neighbor_start_, topo.neighbors_);
  return topo;
}

}  // namespace plumbago
