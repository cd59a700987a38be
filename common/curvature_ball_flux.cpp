// The curvature tensor's ball from its boundary (SPEC §1.1; docs/curvature.md, "The ball
// from its boundary").
//
// Every face F has whole-face terms w(F): its area, its area-weighted normal, and half of
// beta |e| ê êᵀ for each of its sides (an edge between two faces gets its whole term
// from the two halves). Over a spanning forest of the dual graph (faces joined across
// sides of non-zero length), S(F) is the sum of w over F's subtree. For a set R of faces
// that holds no root, sum_R w = sum over the tree links leaving R of S(child in R) -
// sum over the tree links entering R of S(child outside R); a root in R adds its S.
// With R the faces of the ball wholly inside the sphere, every link across R's boundary
// joins a face of R to a face the sphere cuts, so the ball costs what its cut faces cost.
#include <tbb/parallel_for.h>

#include <algorithm>

#include "common/ball_geometry.hpp"
#include "common/curvature_ball.hpp"
#include "common/curvature_memory.hpp"

namespace plumbago::curvature {

namespace {

constexpr uint32_t kNoEdge = ~0u;
constexpr uint32_t kJoined = 8;  // Scratch::CutFace::reach: the face is joined to the first cut face

bool lexicographically_less(const glm::vec3& a, const glm::vec3& b) {
  return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

bool in_ball(const glm::dvec3& p, const glm::dvec3& c, double r) { return glm::dot(p - c, p - c) <= r * r; }

// The fraction of side k inside the ball, the same from both faces of the side (its
// corners in one order), so that a side reaches into the ball for both or for neither.
double side_fraction(const glm::vec3 (&corner)[3], int k, const bool (&inside)[3], const glm::dvec3& c, double r) {
  const glm::vec3 &u = corner[k], &w = corner[(k + 1) % 3];
  if (u == w) return 0;
  if (inside[k] && inside[(k + 1) % 3]) return 1;
  return lexicographically_less(u, w) ? segment_fraction_in_ball(u, w, c, r) : segment_fraction_in_ball(w, u, c, r);
}

// w(F): the whole-face terms of F.
BallSums whole_face_terms(const BallFace& face) {
  BallSums w;
  w.add_whole_face(face.twice_area_normal, face.N_length);
  for (int k = 0; k < 3; ++k)
    w.tensor.add(0.5 * face.beta_per_length[k], glm::dvec3(face.corner[(k + 1) % 3]) - glm::dvec3(face.corner[k]));
  return w;
}

}  // namespace

// The dual forest, breadth first from the lowest face of each piece of the mesh.
BallFlux::DualForest BallFlux::dual_forest(const Surface& g) {
  const uint32_t n = uint32_t(g.faces.size());
  DualForest forest{std::vector<uint32_t>(n, kNoEdge), std::vector<uint32_t>(n, kNoEdge), {}};
  auto& [root, parent_edge, order] = forest;
  order.reserve(n);
  for (uint32_t start = 0; start < n; ++start) {
    if (root[start] != kNoEdge) continue;
    root[start] = start;
    order.push_back(start);
    for (size_t i = order.size() - 1; i < order.size(); ++i) {
      const uint32_t f = order[i];
      const BallFace& face = g.faces[f];
      for (int k = 0; k < 3; ++k) {
        const int32_t a = face.neighbor[k];
        if (a < 0 || root[uint32_t(a)] != kNoEdge || face.corner[k] == face.corner[(k + 1) % 3]) continue;
        root[uint32_t(a)] = start;
        parent_edge[uint32_t(a)] = g.topo.face_edges[f][k];
        order.push_back(uint32_t(a));
      }
    }
  }
  return forest;
}

// The subtree sums, children before parents.
BallFlux::BallFlux(const Surface& g) : g_(g), forest_(dual_forest(g)), bvh_(g.mesh, forest_.root) {
  const size_t n = g.faces.size();
  assign_populated(subtree_, n);
  tbb::parallel_for(size_t(0), n, [&](size_t f) { subtree_[f] = whole_face_terms(g.faces[f]); });
  for (size_t i = n; i-- > 0;) {
    const uint32_t f = forest_.order[i];
    if (forest_.parent_edge[f] == kNoEdge) continue;
    const auto& edge = g.topo.edges[forest_.parent_edge[f]];
    const uint32_t parent = uint32_t(edge.face[0] == int32_t(f) ? edge.face[1] : edge.face[0]);
    subtree_[parent].add(1, subtree_[f]);
  }
  forest_.order = {};
}

std::vector<uint32_t> BallFlux::vertex_order() const {
  std::vector<uint32_t> order;
  order.reserve(g_.mesh.positions.size());
  std::vector<bool> listed(g_.mesh.positions.size());
  for (const FaceBvh::Entry& e : bvh_.entries())
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = g_.mesh.triangles[e.face][k];
      if (!listed[v]) listed[v] = true, order.push_back(v);
    }
  for (uint32_t v = 0; v < listed.size(); ++v)
    if (!listed[v]) order.push_back(v);
  return order;
}

bool BallFlux::sums(uint32_t v, const glm::dvec3& c, double r, Scratch& s, BallSums& out) const {
  const auto faces_of_v = g_.topo.faces_of(v);
  if (faces_of_v.empty()) return false;
  const uint32_t root = forest_.root[faces_of_v[0]];
  for (uint32_t f : faces_of_v)
    if (forest_.root[f] != root) return false;
  // The cut faces of v's piece of the mesh: a corner beyond r and a side reaching in.
  bvh_.for_each_face_near_sphere(c, r, [&](const FaceBvh::Entry& e) {
    if (e.tag != root) return;
    bool inside[3];
    for (int k = 0; k < 3; ++k) inside[k] = in_ball(e.corner[k], c, r);
    if (inside[0] && inside[1] && inside[2]) return;
    Scratch::CutFace cut{0, {0, 0, 0}};
    for (int k = 0; k < 3; ++k)
      if ((cut.fraction[k] = side_fraction(e.corner, k, inside, c, r)) > 0) cut.reach |= 1u << k;
    if (cut.reach == 0) return;
    s.enqueue_face(e.face);
    s.cut.push_back(cut);
  });
  // They must form one band, joined across sides that reach in.
  if (!s.queue.empty()) {
    size_t joined = 1;
    s.cut[0].reach |= kJoined;
    s.stack.assign(1, 0);
    while (!s.stack.empty()) {
      const uint32_t i = s.stack.back();
      s.stack.pop_back();
      const BallFace& face = g_.faces[s.queue[i]];
      for (int k = 0; k < 3; ++k) {
        const int32_t a = face.neighbor[k];
        if (!(s.cut[i].reach >> k & 1) || a < 0 || !s.queued(uint32_t(a))) continue;
        const uint32_t j = s.mark[uint32_t(a)].position;
        if (s.cut[j].reach & kJoined) continue;
        s.cut[j].reach |= kJoined;
        s.stack.push_back(j), ++joined;
      }
    }
    if (joined != s.queue.size()) return false;
  }
  out = BallSums{};
  const BallFace& root_face = g_.faces[root];
  if (in_ball(root_face.corner[0], c, r) && in_ball(root_face.corner[1], c, r) && in_ball(root_face.corner[2], c, r))
    out.add(1, subtree_[root]);
  for (uint32_t i = 0; i < s.queue.size(); ++i) {
    const uint32_t f = s.queue[i];
    const BallFace& face = g_.faces[f];
    const glm::dvec3 p[3] = {face.corner[0], face.corner[1], face.corner[2]};
    out.add_face(triangle_area_in_ball(p[0], p[1], p[2], c, r, face.twice_area_normal, face.N_length),
                 face.twice_area_normal, face.N_length);
    for (int k = 0; k < 3; ++k) {
      const int32_t a = face.neighbor[k];
      if (!(s.cut[i].reach >> k & 1) || a < 0) continue;
      const glm::dvec3 side = p[(k + 1) % 3] - p[k];
      if (s.queued(uint32_t(a))) {  // a cut face too: the side is counted by the lower one
        if (f < uint32_t(a)) out.tensor.add(s.cut[i].fraction[k] * face.beta_per_length[k], side);
        continue;
      }
      // A face wholly inside, whose w(a) holds the other half of this side's term.
      out.tensor.add(0.5 * face.beta_per_length[k], side);
      const uint32_t e = g_.topo.face_edges[f][k];
      if (forest_.parent_edge[uint32_t(a)] == e) out.add(1, subtree_[uint32_t(a)]);
      if (forest_.parent_edge[f] == e) out.add(-1, subtree_[f]);
    }
  }
  return true;
}

}  // namespace plumbago::curvature
