// The sums of the curvature tensor over each vertex's 1-ring or geodesic ball (Lee et al. 2006, §5.3; Alliez et al.
// 2003; curvature.hpp has the definitions).
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>

#include "common/curvature/ball_geometry.hpp"
#include "common/curvature/curvature_internal.hpp"
#include "common/curvature/curvature_memory.hpp"

namespace plumbago::curvature {

namespace {

struct Triangle {
  glm::dvec3 p[3];
  glm::dvec3 side(int k) const { return p[(k + 1) % 3] - p[k]; }  // corner k to corner k + 1
  glm::dvec3 twice_area_normal() const { return glm::cross(p[1] - p[0], p[2] - p[0]); }
};

Triangle triangle(const Mesh& mesh, uint32_t f) {
  const auto& t = mesh.triangles[f];
  return {{mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]}};
}

// Per edge, beta(e) / |e| (0 for a zero-length edge): the edge's term of T is then
// beta |e ∩ B| e eᵀ = beta / |e| x (|e ∩ B| / |e|) d dᵀ, with d = to - from. The 1-ring
// reads everything else straight from the mesh, which keeps the memory it needs (whose
// first touch costs about as much as the 1-ring itself) to these 8 bytes an edge.
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
    // same |N0| |N1| > 0 is the same angle (and 0 where a face has no area).
    glm::dvec3 n0 = triangle(mesh, uint32_t(edge.face[0])).twice_area_normal();
    glm::dvec3 n1 = triangle(mesh, uint32_t(edge.face[1])).twice_area_normal();
    coefficient[e] = signed_dihedral_angle(n0, n1, d / length) / length;
  });
  return coefficient;
}

// Where a face stands in the current vertex's ball: queued as the `position`-th face
// (stamp = the current vertex's), or not yet (any other stamp).
struct FaceMark {
  uint32_t stamp = 0, position = 0;
};

// Per-thread marks of the faces queued for the current vertex (only the ball uses them).
struct Scratch {
  std::vector<FaceMark> mark;
  std::vector<uint32_t> queue;
  uint32_t stamp = 0;
  explicit Scratch(size_t faces) : mark(faces) {}
  void next_vertex() {
    if (++stamp == 0) {
      std::fill(mark.begin(), mark.end(), FaceMark{});
      stamp = 1;
    }
    queue.clear();
  }
  bool queued(uint32_t f) const { return mark[f].stamp == stamp; }
  bool enqueue_face(uint32_t f) {
    if (queued(f)) return false;
    mark[f] = {stamp, uint32_t(queue.size())};
    queue.push_back(f);
    return true;
  }
  // An edge is counted by the first of its faces to leave the queue: the face at
  // `position` counts its side towards `other` unless `other` left the queue before it.
  bool counts_side(int32_t other, uint32_t position) const {
    return other < 0 || !queued(uint32_t(other)) || mark[uint32_t(other)].position > position;
  }
};

// What the ball reads about a face, in one record: the ball visits faces in no useful
// order, and one record is two cache lines where the mesh, the topology and the edge
// coefficients would be five or six. Each side's beta / |e| is kept in both faces of
// its edge, and each side knows the face across it, so the ball never reads an edge.
struct BallFace {
  glm::vec3 corner[3];
  int32_t neighbor[3];           // the face across side k (corner k to k + 1), -1 if none
  double beta_per_length[3];     // of side k's edge
  glm::dvec3 twice_area_normal;  // N
  double N_length;
};

struct Surface {
  const Mesh& mesh;
  const MeshTopology& topo;
  std::vector<double> beta_per_length;
  std::vector<BallFace> faces;  // for the ball only
};

void fill_ball_records(Surface& g) {
  assign_populated(g.faces, g.mesh.triangles.size());
  tbb::parallel_for(size_t(0), g.faces.size(), [&](size_t f) {
    BallFace& face = g.faces[f];
    for (int k = 0; k < 3; ++k) {
      face.corner[k] = g.mesh.positions[g.mesh.triangles[f][k]];
      uint32_t e = g.topo.face_edges[f][k];
      const auto& edge = g.topo.edges[e];
      face.neighbor[k] = edge.face[0] == int32_t(f) ? edge.face[1] : edge.face[0];
      face.beta_per_length[k] = g.beta_per_length[e];
    }
    face.twice_area_normal = triangle(g.mesh, uint32_t(f)).twice_area_normal();
    face.N_length = glm::length(face.twice_area_normal);
  });
}

bool has_corner(const glm::uvec3& t, uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

// 1-ring (radius 0): the faces around v; edges at v whole, edges opposite v half, each
// edge once, from the first of its faces around v (faces_of is sorted). A side is
// skipped where the face across it is around v and comes earlier: the face across a
// side at v always has v as a corner, the face across a side opposite v only where two
// faces share all three vertices.
BallSums one_ring_sums(uint32_t v, const Surface& g) {
  BallSums sums;
  for (uint32_t f : g.topo.faces_of(v)) {
    const Triangle tri = triangle(g.mesh, f);
    glm::dvec3 n = tri.twice_area_normal();
    sums.add_whole_face(n, glm::length(n));
    const auto& t = g.mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const uint32_t e = g.topo.face_edges[f][k];
      const auto& edge = g.topo.edges[e];
      const int32_t across = edge.face[0] == int32_t(f) ? edge.face[1] : edge.face[0];
      const bool at_v = t[k] == v || t[(k + 1) % 3] == v;
      if (across >= 0 && uint32_t(across) < f && (at_v || has_corner(g.mesh.triangles[uint32_t(across)], v))) continue;
      sums.tensor.add((at_v ? 1.0 : 0.5) * g.beta_per_length[e], tri.side(k));
    }
  }
  return sums;
}

// The approximate ball's weight of a piece of surface whose points (corners and middle) lie
// at distances d from the center: 1 when all are inside, 0 when the nearest is outside,
// else (r - d_min) / (d_max - d_min) (issue 19: CGAL 6's interpolated corrected curvatures).
double approximate_weight(std::initializer_list<double> d, double r) {
  auto [lo, hi] = std::minmax(d);
  if (hi <= r) return 1.0;
  if (lo > r) return 0.0;
  return (r - lo) / (hi - lo);
}

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

// The share of side a -> b inside the ball: exact, or approximate.
double side_fraction(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double r, bool exact) {
  if (exact) return segment_fraction_in_ball(a, b, c, r);
  return approximate_weight({distance(a, c), distance(b, c), distance(0.5 * (a + b), c)}, r);
}

// The face's area inside the ball: exact, or approximate.
double area_in_ball(const BallFace& face, const glm::dvec3 (&p)[3], const glm::dvec3& c, double r, bool exact) {
  if (exact) return triangle_area_in_ball(p[0], p[1], p[2], c, r, face.twice_area_normal, face.N_length);
  glm::dvec3 centroid = (p[0] + p[1] + p[2]) / 3.0;
  double w = approximate_weight({distance(p[0], c), distance(p[1], c), distance(p[2], c), distance(centroid, c)}, r);
  return w * 0.5 * face.N_length;
}

// The face at queue position i, clipped to the ball (c, r), exactly or approximately: its
// area, and the sides it counts (see Scratch::counts_side) that reach into the ball; the
// faces across those sides are queued.
void add_face_in_ball(uint32_t i, const glm::dvec3& c, double r, bool exact, const Surface& g, Scratch& s,
                      BallSums& sums) {
  const BallFace& face = g.faces[s.queue[i]];
  const glm::dvec3 p[3] = {face.corner[0], face.corner[1], face.corner[2]};
  bool inside[3];
  for (int k = 0; k < 3; ++k) inside[k] = glm::dot(p[k] - c, p[k] - c) <= r * r;
  if (inside[0] && inside[1] && inside[2])
    sums.add_whole_face(face.twice_area_normal, face.N_length);
  else
    sums.add_face(area_in_ball(face, p, c, r, exact), face.twice_area_normal, face.N_length);
  for (int k = 0; k < 3; ++k) {
    const int32_t other = face.neighbor[k];
    if (!s.counts_side(other, i)) continue;
    const glm::dvec3 side = p[(k + 1) % 3] - p[k];
    bool whole = inside[k] && inside[(k + 1) % 3] && side != glm::dvec3(0);
    double fraction = whole ? 1.0 : side_fraction(p[k], p[(k + 1) % 3], c, r, exact);
    if (!(fraction > 0)) continue;
    sums.tensor.add(fraction * face.beta_per_length[k], side);
    if (other >= 0 && s.enqueue_face(uint32_t(other))) __builtin_prefetch(&g.faces[uint32_t(other)]);
  }
}

// The connected part of the surface within distance r of v, grown face by face across
// edges that reach into the ball; each edge and face clipped exactly or approximately.
BallSums ball_sums(uint32_t v, double r, bool exact, const Surface& g, Scratch& s) {
  BallSums sums;
  const glm::dvec3 c = g.mesh.positions[v];
  for (uint32_t f : g.topo.faces_of(v)) s.enqueue_face(f);
  for (uint32_t i = 0; i < s.queue.size(); ++i) add_face_in_ball(i, c, r, exact, g, s, sums);
  return sums;
}

double ring_radius(uint32_t v, const Mesh& mesh, const MeshTopology& topo) {
  double r = 0;
  for (uint32_t u : topo.neighbors_of(v))
    r = std::max(r, glm::length(glm::dvec3(mesh.positions[u]) - glm::dvec3(mesh.positions[v])));
  return r;
}

}  // namespace

void for_each_vertex_sums(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress,
                          const std::function<void(uint32_t, const BallSums&)>& f) {
  const bool ball = p.radius > 0;
  Surface g{mesh, topo, edge_beta_per_length(mesh, topo), {}};
  if (ball) fill_ball_records(g);
  const double radius = double(p.radius) * double(mesh.bbox_diagonal());
  tbb::enumerable_thread_specific<Scratch> scratch(ball ? mesh.triangles.size() : 0);
  const uint32_t n = uint32_t(mesh.positions.size());
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, n, 1024), [&](const tbb::blocked_range<uint32_t>& range) {
    Scratch& s = scratch.local();
    for (uint32_t v = range.begin(); v != range.end(); ++v) {
      s.next_vertex();
      bool ring = !ball || (p.ring_fallback && radius < ring_radius(v, mesh, topo));
      f(v, ring ? one_ring_sums(v, g) : ball_sums(v, radius, p.ball_clip == BallClip::Exact, g, s));
    }
    progress.advance(range.size());
  });
}

}  // namespace plumbago::curvature
