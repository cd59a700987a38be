// Adjacency of a plumbago::Mesh: edges with their two faces, the edges of each face,
// and the faces and neighbors of each vertex. Built once with OpenMesh's halfedge
// structure (which also tells which faces are non-manifold), then kept as flat arrays
// indexed by the mesh's own vertex and triangle indices, so that parallel loops over
// vertices read plain memory.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "common/mesh.hpp"

namespace plumbago {

struct MeshTopology {
  struct Edge {
    uint32_t from, to;  // mesh vertex indices, in the order face[0] runs along the edge
    int32_t face[2];    // face[1] = -1 on a boundary (and where a non-manifold face was split off)
  };
  std::vector<Edge> edges;
  std::vector<std::array<uint32_t, 3>> face_edges;  // face_edges[f][k]: edge (corner k, corner k+1)
  size_t split_faces = 0;  // faces of non-manifold input that were attached by their own vertices

  std::span<const uint32_t> faces_of(uint32_t v) const {
    return {vertex_faces_.data() + face_start_[v], vertex_faces_.data() + face_start_[v + 1]};
  }
  std::span<const uint32_t> neighbors_of(uint32_t v) const {
    return {neighbors_.data() + neighbor_start_[v], neighbors_.data() + neighbor_start_[v + 1]};
  }
  size_t vertex_count() const { return face_start_.size() - 1; }

 private:
  friend MeshTopology build_topology(const Mesh& mesh);
  std::vector<uint32_t> face_start_, vertex_faces_;    // CSR: faces around each vertex
  std::vector<uint32_t> neighbor_start_, neighbors_;   // CSR: vertices sharing an edge, sorted
};

// Refuses (MeshError) only what validate_mesh refuses; any triangle soup is accepted.
MeshTopology build_topology(const Mesh& mesh);

}  // namespace plumbago
