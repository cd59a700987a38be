#include "common/curvature_clusters.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

namespace plumbago::curvature {
namespace {

constexpr size_t kGroup = 8;  // faces per level-1 cluster, clusters per parent
constexpr int kMaxLevels = 12;

// Groups of up to kGroup items, each grown breadth-first from the lowest item left
// across adjacent(item, visit). Returns the group count; group[item] is its group.
template <class Adjacent>
uint32_t greedy_groups(size_t items, const Adjacent& adjacent, std::vector<uint32_t>& group) {
  group.assign(items, UINT32_MAX);
  std::vector<uint32_t> queue;
  uint32_t count = 0;
  for (uint32_t seed = 0; seed < items; ++seed) {
    if (group[seed] != UINT32_MAX) continue;
    group[seed] = count;
    queue.assign(1, seed);
    for (size_t i = 0; i < queue.size() && queue.size() < kGroup; ++i)
      adjacent(queue[i], [&](uint32_t other) {
        if (queue.size() < kGroup && group[other] == UINT32_MAX) group[other] = count, queue.push_back(other);
      });
    ++count;
  }
  return count;
}

// visit(g) for each face g across a positive-length edge of face f.
template <class Visit>
void faces_across(const Mesh& mesh, const MeshTopology& topo, uint32_t f, const Visit& visit) {
  const Triangle tri = triangle(mesh, f);
  for (int k = 0; k < 3; ++k) {
    if (tri.side(k) == glm::dvec3(0)) continue;
    for (int32_t g : topo.edges[topo.face_edges[f][k]].face)
      if (g >= 0 && uint32_t(g) != f) visit(uint32_t(g));
  }
}

// Members of each group, as CSR lists in item order.
void group_members(const std::vector<uint32_t>& group, uint32_t count, std::vector<uint32_t>& start,
                   std::vector<uint32_t>& members) {
  start.assign(count + 1, 0);
  for (uint32_t g : group) ++start[g + 1];
  std::inclusive_scan(start.begin(), start.end(), start.begin());
  members.resize(group.size());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (uint32_t i = 0; i < group.size(); ++i) members[fill[group[i]]++] = i;
}

// Sorted, without repeats.
void sort_unique(std::vector<uint32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// A level-1 cluster: its faces' sums and the edges whose face[0] it holds, a sphere
// around their corners (centered on their mean), and the faces across its edges.
FaceClusters::Node face_cluster(std::span<const uint32_t> faces, uint32_t self, const Mesh& mesh,
                                const MeshTopology& topo, const std::vector<double>& beta_per_length,
                                const std::vector<uint32_t>& face_node, std::vector<uint32_t>& boundary) {
  FaceClusters::Node node{glm::dvec3(0), 0, -1, 0, 0, {}};
  for (uint32_t f : faces) {
    const Triangle tri = triangle(mesh, f);
    glm::dvec3 n = tri.twice_area_normal();
    node.sums.add_whole_face(n, glm::length(n));
    for (int k = 0; k < 3; ++k) {
      uint32_t e = topo.face_edges[f][k];
      if (uint32_t(topo.edges[e].face[0]) == f) node.sums.tensor.add(beta_per_length[e], tri.side(k));
      node.center += tri.p[k] / double(3 * faces.size());
    }
    faces_across(mesh, topo, f, [&](uint32_t g) {
      if (face_node[g] != self) boundary.push_back(g);
    });
  }
  for (uint32_t f : faces)
    for (const glm::dvec3& p : triangle(mesh, f).p) node.radius = std::max(node.radius, glm::length(p - node.center));
  return node;
}

// A cluster of clusters: the sum of its children's sums, a sphere around their spheres
// (centered on the mean of their centers), and the faces across their boundaries that
// are not its own.
FaceClusters::Node parent_cluster(std::span<const uint32_t> children, uint32_t self, const FaceClusters& h,
                                  const std::vector<uint32_t>& face_top, std::vector<uint32_t>& boundary) {
  FaceClusters::Node node{glm::dvec3(0), 0, -1, 0, 0, {}};
  for (uint32_t c : children) {
    node.sums.add(h.nodes[c].sums);
    node.center += h.nodes[c].center / double(children.size());
    for (uint32_t i = h.nodes[c].boundary_begin; i < h.nodes[c].boundary_end; ++i)
      if (face_top[h.boundary_faces[i]] != self) boundary.push_back(h.boundary_faces[i]);
  }
  for (uint32_t c : children)
    node.radius = std::max(node.radius, glm::length(h.nodes[c].center - node.center) + h.nodes[c].radius);
  return node;
}

// Appends one level's nodes (node_of(i, boundary) builds the i-th), their boundaries
// sorted and without repeats.
template <class NodeOf>
void append_level(uint32_t count, const NodeOf& node_of, FaceClusters& h) {
  std::vector<FaceClusters::Node> level(count);
  std::vector<std::vector<uint32_t>> boundaries(count);
  tbb::parallel_for(uint32_t(0), count, [&](uint32_t i) {
    level[i] = node_of(i, boundaries[i]);
    sort_unique(boundaries[i]);
  });
  for (uint32_t i = 0; i < count; ++i) {
    level[i].boundary_begin = uint32_t(h.boundary_faces.size());
    h.boundary_faces.insert(h.boundary_faces.end(), boundaries[i].begin(), boundaries[i].end());
    level[i].boundary_end = uint32_t(h.boundary_faces.size());
    h.nodes.push_back(level[i]);
  }
}

}  // namespace

FaceClusters build_face_clusters(const Mesh& mesh, const MeshTopology& topo, const std::vector<double>& beta_per_length) {
  FaceClusters h;
  std::vector<uint32_t> group, start, members;
  uint32_t count = greedy_groups(
      mesh.triangles.size(), [&](uint32_t f, const auto& visit) { faces_across(mesh, topo, f, visit); }, group);
  h.face_node = group;
  group_members(group, count, start, members);
  append_level(count, [&](uint32_t i, std::vector<uint32_t>& boundary) {
    std::span<const uint32_t> faces(members.data() + start[i], members.data() + start[i + 1]);
    return face_cluster(faces, i, mesh, topo, beta_per_length, h.face_node, boundary);
  }, h);
  std::vector<uint32_t> face_top = h.face_node;  // each face's cluster at the highest level so far
  uint32_t first = 0;                            // that level's first node
  for (int level = 2; level <= kMaxLevels && count > 1; ++level) {
    auto adjacent = [&](uint32_t i, const auto& visit) {
      const auto& n = h.nodes[first + i];
      for (uint32_t b = n.boundary_begin; b < n.boundary_end; ++b) visit(face_top[h.boundary_faces[b]] - first);
    };
    uint32_t parents = greedy_groups(count, adjacent, group);
    if (parents == count) break;
    const uint32_t base = uint32_t(h.nodes.size());
    for (uint32_t i = 0; i < count; ++i) h.nodes[first + i].parent = int32_t(base + group[i]);
    for (auto& top : face_top) top = uint32_t(h.nodes[top].parent);
    group_members(group, parents, start, members);
    append_level(parents, [&](uint32_t i, std::vector<uint32_t>& boundary) {
      std::vector<uint32_t> children;
      for (uint32_t m = start[i]; m < start[i + 1]; ++m) children.push_back(first + members[m]);
      return parent_cluster(children, base + i, h, face_top, boundary);
    }, h);
    first = base, count = parents;
  }
  return h;
}

}  // namespace plumbago::curvature
