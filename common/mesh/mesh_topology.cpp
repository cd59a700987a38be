#include "common/mesh/mesh_topology.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <atomic>
#include <numeric>

#include "common/curvature/curvature_memory.hpp"

namespace plumbago {
namespace {

using curvature::assign_populated;

// --- CSR lists, built in parallel ----------------------------------------------------

// f(key, this thread's scratch) for every key in [0, keys), in parallel: the scratch is
// looked up once per range, not once per key.
template <class Scratch, class F>
void for_each_key(size_t keys, tbb::enumerable_thread_specific<Scratch>& scratch, const F& f) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, keys), [&](const tbb::blocked_range<size_t>& range) {
    Scratch& local = scratch.local();
    for (size_t k = range.begin(); k != range.end(); ++k) f(uint32_t(k), local);
  });
}

// start[k + 1] = start[k] + count[k + 1], in place (count[0] = 0).
void counts_to_starts(std::vector<uint32_t>& count) { std::inclusive_scan(count.begin(), count.end(), count.begin()); }

// CSR of the lists list(key, out) writes (two passes: count, then copy).
template <class List>
void gather_csr(size_t keys, const List& list, std::vector<uint32_t>& start, std::vector<uint32_t>& values) {
  tbb::enumerable_thread_specific<std::vector<uint32_t>> scratch;
  assign_populated(start, keys + 1);
  for_each_key(keys, scratch, [&](uint32_t k, std::vector<uint32_t>& out) {
    list(k, out);
    start[k + 1] = uint32_t(out.size());
  });
  counts_to_starts(start);
  assign_populated(values, start[keys]);
  for_each_key(keys, scratch, [&](uint32_t k, std::vector<uint32_t>& out) {
    list(k, out);
    std::copy(out.begin(), out.end(), values.begin() + start[k]);
  });
}

// Calls f(corner, face) once for each distinct corner of each face, in parallel.
template <class F>
void for_each_distinct_corner(const Mesh& mesh, const F& f) {
  tbb::parallel_for(size_t(0), mesh.triangles.size(), [&](size_t face) {
    const auto& t = mesh.triangles[face];
    for (int k = 0; k < 3; ++k)
      if ((k < 1 || t[k] != t[0]) && (k < 2 || t[k] != t[1])) f(t[k], uint32_t(face));
  });
}

// CSR of the faces around each vertex, each list sorted: counted and scattered with
// atomic counters, then sorted list by list.
void fill_vertex_faces(const Mesh& mesh, std::vector<uint32_t>& start, std::vector<uint32_t>& faces) {
  const size_t n = mesh.positions.size();
  assign_populated(start, n + 1);
  for_each_distinct_corner(mesh, [&](uint32_t v, uint32_t) {
    std::atomic_ref<uint32_t>(start[v + 1]).fetch_add(1, std::memory_order_relaxed);
  });
  counts_to_starts(start);
  assign_populated(faces, start[n]);
  std::vector<uint32_t> cursor;
  assign_populated(cursor, n);
  std::copy(start.begin(), start.end() - 1, cursor.begin());
  for_each_distinct_corner(mesh, [&](uint32_t v, uint32_t f) {
    faces[std::atomic_ref<uint32_t>(cursor[v]).fetch_add(1, std::memory_order_relaxed)] = f;
  });
  tbb::parallel_for(size_t(0), n, [&](size_t v) { std::sort(faces.begin() + start[v], faces.begin() + start[v + 1]); });
}

// --- Manifold meshes: neighbors and edges vertex by vertex ---------------------------

// v's corner in one of its faces: v = t[slot], next = t[slot + 1], prev = t[slot + 2].
struct Corner {
  uint32_t face, slot, next, prev;
};

// Up to this many corners (a vertex has 6 on average) a corner is found by scanning
// them, which costs less than sorting them; above it, by binary search.
constexpr size_t kScannedCorners = 16;

// Finds the corner whose next (or prev) is a given vertex.
class CornerIndex {
 public:
  void build(const std::vector<Corner>& corners, uint32_t Corner::*field) {
    corners_ = &corners, field_ = field;
    pairs_.clear();
    if (corners.size() <= kScannedCorners) return;
    for (uint32_t i = 0; i < corners.size(); ++i) pairs_.emplace_back(corners[i].*field, i);
    std::sort(pairs_.begin(), pairs_.end());
  }
  bool has_repeats() const {
    const auto& c = *corners_;
    if (pairs_.empty()) {
      for (size_t i = 1; i < c.size(); ++i)
        for (size_t j = 0; j < i; ++j)
          if (c[i].*field_ == c[j].*field_) return true;
      return false;
    }
    return std::adjacent_find(pairs_.begin(), pairs_.end(), [](auto a, auto b) { return a.first == b.first; }) !=
           pairs_.end();
  }
  int find(uint32_t value) const {
    if (pairs_.empty()) {
      for (size_t i = 0; i < corners_->size(); ++i)
        if ((*corners_)[i].*field_ == value) return int(i);
      return -1;
    }
    auto it = std::lower_bound(pairs_.begin(), pairs_.end(), std::make_pair(value, 0u));
    return it != pairs_.end() && it->first == value ? int(it->second) : -1;
  }

 private:
  const std::vector<Corner>* corners_ = nullptr;
  uint32_t Corner::*field_ = nullptr;
  std::vector<std::pair<uint32_t, uint32_t>> pairs_;  // (value, corner) sorted, for large fans only
};

struct VertexCorners {
  std::vector<Corner> corners;
  CornerIndex by_next, by_prev;
  int open_start = -1;  // of a vertex that is one fan: its open fan's first corner, -1 if closed
};

// The corners of v in its faces; false where v is a corner of one face twice.
bool collect_corners(uint32_t v, const Mesh& mesh, std::span<const uint32_t> faces, VertexCorners& c) {
  c.corners.clear();
  for (uint32_t f : faces) {
    const auto& t = mesh.triangles[f];
    int slot = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    if ((t[0] == v) + (t[1] == v) + (t[2] == v) != 1) return false;
    c.corners.push_back({f, uint32_t(slot), t[(slot + 1) % 3], t[(slot + 2) % 3]});
  }
  c.by_next.build(c.corners, &Corner::next);
  c.by_prev.build(c.corners, &Corner::prev);
  return true;
}

// The corners whose prev edge has no face running the other way (the start of an open
// fan): how many; c.open_start is the last of them, -1 if none.
size_t fan_starts(VertexCorners& c) {
  size_t starts = 0;
  c.open_start = -1;
  for (size_t i = 0; i < c.corners.size(); ++i)
    if (c.by_next.find(c.corners[i].prev) < 0) ++starts, c.open_start = int(i);
  return starts;
}

// Every edge at v has at most one face running out of v along it (next) and one running
// into v (prev), and the faces, each linked to the one across its edge (v, next), form
// one path (an open fan, starting at the only face whose prev edge has no other face) or
// one cycle (a closed fan).
bool is_one_fan(VertexCorners& c) {
  c.open_start = -1;
  if (c.corners.empty()) return true;
  if (c.by_next.has_repeats() || c.by_prev.has_repeats()) return false;
  if (fan_starts(c) > 1) return false;
  const size_t start = c.open_start < 0 ? 0 : size_t(c.open_start);
  size_t visited = 1;
  for (int i = int(start);;) {
    int j = c.by_prev.find(c.corners[size_t(i)].next);
    if (j < 0 || size_t(j) == start) break;
    if (++visited > c.corners.size()) return false;
    i = j;
  }
  return visited == c.corners.size();
}

// The neighbors of a vertex that is one fan (c.open_start set by is_one_fan or
// fan_starts), unsorted: every corner's next (each corner's prev is the next of the
// corner before it) and, for an open fan, the start's prev. Calls f(u) for each.
template <class F>
void for_each_fan_neighbor(const VertexCorners& c, const F& f) {
  for (const Corner& k : c.corners) f(k.next);
  if (c.open_start >= 0) f(c.corners[size_t(c.open_start)].prev);
}

// Edge `e` = (v, u): face[0] is the lower of its faces, from -> to the way it runs.
void write_edge(uint32_t e, uint32_t v, uint32_t u, const VertexCorners& c, MeshTopology& topo) {
  int out = c.by_next.find(u), in = c.by_prev.find(u);  // faces running v -> u and u -> v
  MeshTopology::Edge edge{v, u, {-1, -1}};
  if (out >= 0) {
    const Corner& k = c.corners[size_t(out)];
    topo.face_edges[k.face][k.slot] = e;
    edge.face[0] = int32_t(k.face);
  }
  if (in >= 0) {
    const Corner& k = c.corners[size_t(in)];
    topo.face_edges[k.face][(k.slot + 2) % 3] = e;
    edge.face[1] = int32_t(k.face);
    if (out < 0 || k.face < uint32_t(edge.face[0])) edge = {u, v, {int32_t(k.face), edge.face[0]}};
  }
  topo.edges[e] = edge;
}

}  // namespace

// Neighbors (CSR `neighbor_start`, `neighbors`) and edges of a mesh whose every vertex is
// one fan, in two passes over each vertex's corners: the counts of neighbors and of the
// edges each vertex owns (those to higher neighbors), then the sorted lists and the edges,
// numbered vertex by vertex. False (the topology unfinished) if some vertex is not one
// fan or some face has a repeated corner.
bool manifold_adjacency(const Mesh& mesh, MeshTopology& topo, std::vector<uint32_t>& neighbor_start,
                        std::vector<uint32_t>& neighbors) {
  const size_t n = mesh.positions.size();
  std::vector<uint32_t> first;  // first[v]: the first edge v owns
  assign_populated(neighbor_start, n + 1);
  assign_populated(first, n + 1);
  tbb::enumerable_thread_specific<VertexCorners> scratch;
  std::atomic<bool> manifold = true;
  for_each_key(n, scratch, [&](uint32_t v, VertexCorners& c) {
    if (!collect_corners(v, mesh, topo.faces_of(v), c) || !is_one_fan(c)) {
      manifold.store(false, std::memory_order_relaxed);
      return;
    }
    for_each_fan_neighbor(c, [&](uint32_t u) { ++neighbor_start[v + 1], first[v + 1] += u > v; });
  });
  if (!manifold) return false;
  counts_to_starts(neighbor_start);
  counts_to_starts(first);
  assign_populated(neighbors, neighbor_start[n]);
  assign_populated(topo.edges, first[n]);
  assign_populated(topo.face_edges, mesh.triangles.size());
  for_each_key(n, scratch, [&](uint32_t v, VertexCorners& c) {
    collect_corners(v, mesh, topo.faces_of(v), c);
    fan_starts(c);
    auto list = neighbors.begin() + neighbor_start[v], end = neighbors.begin() + neighbor_start[v + 1];
    for_each_fan_neighbor(c, [&](uint32_t u) { *list++ = u; });
    list = neighbors.begin() + neighbor_start[v];
    std::sort(list, end);
    auto higher = std::upper_bound(list, end, v);
    for (uint32_t e = first[v]; higher != end; ++higher, ++e) write_edge(e, v, *higher, c, topo);
  });
  return true;
}

namespace {

// --- Any triangle soup: OpenMesh -----------------------------------------------------

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
  topo.face_edges.clear();
  topo.face_edges.reserve(mesh.triangles.size());
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

void openmesh_edges(const Mesh& mesh, MeshTopology& topo) {
  std::vector<uint32_t> mesh_vertex;
  OmMesh om = build_halfedge_mesh(mesh, mesh_vertex, topo);
  topo.edges.resize(om.n_edges());
  for (auto e : om.edges()) {
    auto h0 = om.halfedge_handle(e, 0), h1 = om.halfedge_handle(e, 1);
    if (!om.face_handle(h0).is_valid()) std::swap(h0, h1);
    auto& edge = topo.edges[size_t(e.idx())];
    edge.from = mesh_vertex[size_t(om.from_vertex_handle(h0).idx())];
    edge.to = mesh_vertex[size_t(om.to_vertex_handle(h0).idx())];
    edge.face[0] = om.face_handle(h0).idx();
    edge.face[1] = om.face_handle(h1).is_valid() ? om.face_handle(h1).idx() : -1;
  }
}

}  // namespace

// The faces around each vertex and its neighbors: the other corners of those faces
// (every edge of the topology is a side of some face, split or not).
MeshTopology vertex_topology(const Mesh& mesh) {
  MeshTopology topo;
  fill_vertex_faces(mesh, topo.face_start_, topo.vertex_faces_);
  auto other_corners = [&](uint32_t v, std::vector<uint32_t>& out) {
    out.clear();
    for (uint32_t f : topo.faces_of(v))
      for (int k = 0; k < 3; ++k)
        if (mesh.triangles[f][k] != v) out.push_back(mesh.triangles[f][k]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  };
  gather_csr(mesh.positions.size(), other_corners, topo.neighbor_start_, topo.neighbors_);
  return topo;
}

MeshTopology build_topology(const Mesh& mesh) {
  validate_mesh(mesh);
  MeshTopology topo;
  fill_vertex_faces(mesh, topo.face_start_, topo.vertex_faces_);
  if (manifold_adjacency(mesh, topo, topo.neighbor_start_, topo.neighbors_)) return topo;
  topo = vertex_topology(mesh);
  openmesh_edges(mesh, topo);
  return topo;
}

MeshTopology build_topology_with_openmesh(const Mesh& mesh) {
  validate_mesh(mesh);
  MeshTopology topo = vertex_topology(mesh);
  openmesh_edges(mesh, topo);
  return topo;
}

}  // namespace plumbago
