// The sums of the curvature tensor over each vertex's 1-ring or geodesic ball (SPEC §1.1;
// curvature.hpp has the definitions).
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "common/ball_geometry.hpp"
#include "common/curvature_clusters.hpp"
#include "common/curvature_memory.hpp"

namespace plumbago::curvature {

// Faces and edges are otherwise read straight from the mesh, which keeps the memory the
// 1-ring needs (and its first touch, which costs about as much as the 1-ring) to 8 bytes
// an edge.
std::vector<double> edge_beta_per_length(const Mesh& mesh, const MeshTopology& topo) {
  std::vector<double> coefficient;
  assign_populated(coefficient, topo.edges.size());
  tbb::parallel_for(size_t(0), topo.edges.size(), [&](size_t e) {
    const auto& edge = topo.edges[e];
    glm::dvec3 d = glm::dvec3(mesh.positions[edge.to]) - glm::dvec3(mesh.positions[edge.from]);
    double length = glm::length(d);
    if (edge.face[1] < 0 || !(length > 0)) {
      coefficient[e] = 0;
      return;
    }
    // beta from the faces' N = 2 x area x normal: atan2 of both arguments scaled by the
    // same |N0| |N1| > 0 is the same angle (and 0 where a face has no area, as before).
    glm::dvec3 n0 = triangle(mesh, uint32_t(edge.face[0])).twice_area_normal();
    glm::dvec3 n1 = triangle(mesh, uint32_t(edge.face[1])).twice_area_normal();
    coefficient[e] = signed_dihedral_angle(n0, n1, d / length) / length;
  });
  return coefficient;
}

namespace {

// Per-thread marks of the faces, edges and clusters already visited for the current
// vertex (only the ball uses them: the 1-ring's few edges are kept in the short `queue`).
struct Scratch {
  std::vector<uint32_t> face_mark, edge_mark, node_mark, queue;
  uint32_t stamp = 0;
  Scratch(size_t faces, size_t edges, size_t nodes) : face_mark(faces, 0), edge_mark(edges, 0), node_mark(nodes, 0) {}
  void next_vertex() {
    if (++stamp == 0) {
      for (auto* marks : {&face_mark, &edge_mark, &node_mark}) std::fill(marks->begin(), marks->end(), 0);
      stamp = 1;
    }
    queue.clear();
  }
  bool first_visit(std::vector<uint32_t>& marks, uint32_t i) {
    if (marks[i] == stamp) return false;
    marks[i] = stamp;
    return true;
  }
  void enqueue_face(uint32_t f) {
    if (first_visit(face_mark, f)) queue.push_back(f);
  }
};

struct Surface {
  const Mesh& mesh;
  const MeshTopology& topo;
  std::vector<double> beta_per_length;
  FaceClusters clusters;  // empty: every ball grown face by face
};

// 1-ring (radius 0): the faces around v; edges at v whole, edges opposite v half.
BallSums one_ring_sums(uint32_t v, const Surface& g, Scratch& s) {
  BallSums sums;
  for (uint32_t f : g.topo.faces_of(v)) {
    const Triangle tri = triangle(g.mesh, f);
    glm::dvec3 n = tri.twice_area_normal();
    sums.add_whole_face(n, glm::length(n));
    const auto& t = g.mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      uint32_t e = g.topo.face_edges[f][k];
      if (std::find(s.queue.begin(), s.queue.end(), e) != s.queue.end()) continue;
      s.queue.push_back(e);
      double weight = t[k] == v || t[(k + 1) % 3] == v ? 1.0 : 0.5;
      sums.tensor.add(weight * g.beta_per_length[e], tri.side(k));
    }
  }
  return sums;
}

// Face f's part of the ball (c, r), clipped exactly: its area, and the edges not yet
// seen that reach into the ball, except those a cluster inside the ball adds; the faces
// across those edges are queued.
void add_face_in_ball(uint32_t f, const glm::dvec3& c, double r, const Surface& g, Scratch& s, BallSums& sums) {
  const Triangle tri = triangle(g.mesh, f);
  const glm::dvec3* p = tri.p;
  bool inside[3];
  for (int k = 0; k < 3; ++k) inside[k] = glm::dot(p[k] - c, p[k] - c) <= r * r;
  glm::dvec3 n = tri.twice_area_normal();
  if (inside[0] && inside[1] && inside[2])
    sums.add_whole_face(n, glm::length(n));
  else
    sums.add_face(triangle_area_in_ball(p[0], p[1], p[2], c, r), n, glm::length(n));
  for (int k = 0; k < 3; ++k) {
    uint32_t e = g.topo.face_edges[f][k];
    if (!s.first_visit(s.edge_mark, e)) continue;
    const auto& edge = g.topo.edges[e];
    bool whole = inside[k] && inside[(k + 1) % 3] && tri.side(k) != glm::dvec3(0);
    double fraction = whole ? 1.0 : segment_fraction_in_ball(p[k], p[(k + 1) % 3], c, r);
    if (!(fraction > 0)) continue;
    bool in_cluster = !g.clusters.nodes.empty() && g.clusters.inside(g.clusters.face_node[uint32_t(edge.face[0])], c, r);
    if (!in_cluster) sums.tensor.add(fraction * g.beta_per_length[e], tri.side(k));
    for (int32_t other : edge.face)
      if (other >= 0) s.enqueue_face(uint32_t(other));
  }
}

// The connected part of the surface within distance r of v, grown across edges that
// reach into the ball: a face whose cluster lies inside the ball adds the highest such
// cluster around it whole and queues the faces across its boundary; any other face is
// clipped exactly (curvature_clusters.hpp says why the sums are the same).
BallSums ball_sums(uint32_t v, double r, const Surface& g, Scratch& s) {
  BallSums sums;
  const glm::dvec3 c = g.mesh.positions[v];
  const bool clusters = !g.clusters.nodes.empty();
  for (uint32_t f : g.topo.faces_of(v)) s.enqueue_face(f);
  for (size_t next = 0; next < s.queue.size(); ++next) {
    const uint32_t f = s.queue[next];
    if (clusters && s.node_mark[g.clusters.face_node[f]] == s.stamp) continue;  // added with its cluster
    int32_t node = clusters ? g.clusters.highest_inside(f, c, r) : -1;
    if (node < 0) {
      add_face_in_ball(f, c, r, g, s, sums);
      continue;
    }
    if (s.first_visit(s.node_mark, uint32_t(node))) {
      const auto& cluster = g.clusters.nodes[size_t(node)];
      sums.add(cluster.sums);
      for (uint32_t b = cluster.boundary_begin; b < cluster.boundary_end; ++b)
        s.enqueue_face(g.clusters.boundary_faces[b]);
    }
    s.node_mark[g.clusters.face_node[f]] = s.stamp;  // added with `node`, its ancestor or itself
  }
  return sums;
}

double ring_radius(uint32_t v, const Mesh& mesh, const MeshTopology& topo) {
  double r = 0;
  for (uint32_t u : topo.neighbors_of(v))
    r = std::max(r, glm::length(glm::dvec3(mesh.positions[u]) - glm::dvec3(mesh.positions[v])));
  return r;
}

}  // namespace

void for_each_vertex_sums(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, bool clusters,
                          Progress& progress, const std::function<void(uint32_t, const BallSums&)>& f) {
  const bool ball = p.radius > 0;
  Surface g{mesh, topo, edge_beta_per_length(mesh, topo), {}};
  if (ball && clusters) g.clusters = build_face_clusters(mesh, topo, g.beta_per_length);
  const double radius = double(p.radius) * double(mesh.bbox_diagonal());
  tbb::enumerable_thread_specific<Scratch> scratch(ball ? mesh.triangles.size() : 0, ball ? topo.edges.size() : 0,
                                                   g.clusters.nodes.size());
  const uint32_t n = uint32_t(mesh.positions.size());
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, n, 1024), [&](const tbb::blocked_range<uint32_t>& range) {
    Scratch& s = scratch.local();
    for (uint32_t v = range.begin(); v != range.end(); ++v) {
      s.next_vertex();
      bool ring = !ball || (p.ring_fallback && radius < ring_radius(v, mesh, topo));
      f(v, ring ? one_ring_sums(v, g, s) : ball_sums(v, radius, g, s));
    }
    progress.advance(range.size());
  });
}

}  // namespace plumbago::curvature
