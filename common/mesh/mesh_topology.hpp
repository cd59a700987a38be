// Adjacency of a plumbago::Mesh: edges with their two faces, the edges of each face,
// and the faces and neighbors of each vertex, as flat arrays indexed by the mesh's own
// vertex and triangle indices, so that parallel loops over vertices read plain memory.
// Built in parallel, vertex by vertex, where every edge and vertex is manifold; any other
// triangle soup goes through OpenMesh's halfedge structure (one thread), which decides
// which faces to split off.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago {

struct MeshTopology {
  struct Edge {
    uint32_t from, to;  // mesh vertex indices, in the order face[0] runs along the edge
    int32_t face[2];    // face[1] = -1 on a boundary (and where a non-manifold face was split off)
    bool operator==(const Edge&) const = default;
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
  friend MeshTopology vertex_topology(const Mesh& mesh);
  friend MeshTopology build_topology(const Mesh& mesh);
  std::vector<uint32_t> face_start_, vertex_faces_;   // CSR: faces around each vertex, sorted
  std::vector<uint32_t> neighbor_start_, neighbors_;  // CSR: vertices sharing an edge, sorted
};

// Refuses (MeshError) only what validate_mesh refuses; any triangle soup is accepted.
// Where every edge has at most two faces, running along it in opposite directions, and
// the faces around every vertex form one fan, no face is split, face[0] is the lower
// face index of the edge, and the edges are numbered by their lower vertex.
MeshTopology build_topology(const Mesh& mesh);

// The same through OpenMesh for any input (build_topology's fallback): faces are added
// in order, and a face OpenMesh refuses (a third face on an edge, an orientation that
// disagrees with a neighbor's, a vertex whose fan is closed, a repeated corner) is split
// off: attached by copies of its corners, so its edges are boundary edges. Edges are
// numbered in the order the faces first use them.
MeshTopology build_topology_with_openmesh(const Mesh& mesh);

}  // namespace plumbago
