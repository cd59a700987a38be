// The curvature tensor of Cohen-Steiner & Morvan (Alliez et al. 2003, §3), SPEC §1.1.
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "common/ball_geometry.hpp"
#include "common/curvature_internal.hpp"
#include "common/curvature_memory.hpp"

namespace plumbago {
namespace curvature {

double signed_dihedral_angle(const glm::dvec3& n0, const glm::dvec3& n1, const glm::dvec3& along) {
  return std::atan2(glm::dot(glm::cross(n0, n1), along), glm::dot(n0, n1));
}

void tangent_basis(const glm::dvec3& n, glm::dvec3& t1, glm::dvec3& t2) {
  double sign = std::copysign(1.0, n.z);
  double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
  t1 = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  t2 = glm::dvec3(b, sign + n.y * n.y * a, -n.y);
}

namespace {

// Symmetric 3x3 sum of w ê êᵀ.
struct SymmetricTensor {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
  void add(double w, const glm::dvec3& e) {
    xx += w * e.x * e.x, xy += w * e.x * e.y, xz += w * e.x * e.z;
    yy += w * e.y * e.y, yz += w * e.y * e.z, zz += w * e.z * e.z;
  }
  glm::dvec3 apply(const glm::dvec3& v) const {
    return {xx * v.x + xy * v.y + xz * v.z, xy * v.x + yy * v.y + yz * v.z, xz * v.x + yz * v.y + zz * v.z};
  }
};

glm::dvec3 unit_or_zero(const glm::dvec3& v) {
  double len = glm::length(v);
  return len > 0 && std::isfinite(len) ? v / len : glm::dvec3(0);
}

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
// beta |e ∩ B| ê êᵀ = beta / |e| x (|e ∩ B| / |e|) d dᵀ, with d = to - from. Faces and
// edges are otherwise read straight from the mesh, which keeps the memory this needs
// (and its first touch, which costs about as much as the 1-ring) to 8 bytes an edge.
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
    glm::dvec3 n0 = unit_or_zero(triangle(mesh, uint32_t(edge.face[0])).twice_area_normal());
    glm::dvec3 n1 = unit_or_zero(triangle(mesh, uint32_t(edge.face[1])).twice_area_normal());
    coefficient[e] = signed_dihedral_angle(n0, n1, d / length) / length;
  });
  return coefficient;
}

// The sums over B for one vertex: T (not yet divided by |B|), |B|, and the area-weighted
// face normal.
struct BallSums {
  SymmetricTensor tensor;
  double area = 0;
  glm::dvec3 normal{0};
  // The part of a face inside B, of area a, with the face's unit normal n = N / |N|
  // (N = twice the face's area-weighted normal, so a whole face adds N / 2).
  void add_face(double a, const glm::dvec3& N, double N_length) {
    area += a;
    if (N_length > 0) normal += (a / N_length) * N;
  }
};

// Per-thread marks of the faces and edges already visited for the current vertex (only
// the ball uses them: the 1-ring's few edges are kept in the short `queue`).
struct Scratch {
  std::vector<uint32_t> face_mark, edge_mark, queue;
  uint32_t stamp = 0;
  Scratch(size_t faces, size_t edges) : face_mark(faces, 0), edge_mark(edges, 0) {}
  void next_vertex() {
    if (++stamp == 0) {
      std::fill(face_mark.begin(), face_mark.end(), 0);
      std::fill(edge_mark.begin(), edge_mark.end(), 0);
      stamp = 1;
    }
    queue.clear();
  }
  bool first_visit(std::vector<uint32_t>& marks, uint32_t i) {
    if (marks[i] == stamp) return false;
    marks[i] = stamp;
    return true;
  }
};

struct Surface {
  const Mesh& mesh;
  const MeshTopology& topo;
  std::vector<double> beta_per_length;
};

// 1-ring (radius 0): the faces around v; edges at v whole, edges opposite v half.
BallSums one_ring_sums(uint32_t v, const Surface& g, Scratch& s) {
  BallSums sums;
  for (uint32_t f : g.topo.faces_of(v)) {
    const Triangle tri = triangle(g.mesh, f);
    glm::dvec3 n = tri.twice_area_normal();
    double n_length = glm::length(n);
    sums.add_face(0.5 * n_length, n, n_length);
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

// The connected part of the surface within distance r of v, grown face by face across
// edges that reach into the ball; each edge and face clipped exactly.
BallSums ball_sums(uint32_t v, double r, const Surface& g, Scratch& s) {
  BallSums sums;
  const glm::dvec3 c = g.mesh.positions[v];
  for (uint32_t f : g.topo.faces_of(v))
    if (s.first_visit(s.face_mark, f)) s.queue.push_back(f);
  for (size_t next = 0; next < s.queue.size(); ++next) {
    const uint32_t f = s.queue[next];
    const Triangle tri = triangle(g.mesh, f);
    const glm::dvec3* p = tri.p;
    bool inside[3];
    for (int k = 0; k < 3; ++k) inside[k] = glm::dot(p[k] - c, p[k] - c) <= r * r;
    glm::dvec3 n = tri.twice_area_normal();
    double n_length = glm::length(n);
    sums.add_face(inside[0] && inside[1] && inside[2] ? 0.5 * n_length : triangle_area_in_ball(p[0], p[1], p[2], c, r),
                  n, n_length);
    for (int k = 0; k < 3; ++k) {
      uint32_t e = g.topo.face_edges[f][k];
      if (!s.first_visit(s.edge_mark, e)) continue;
      double fraction = inside[k] && inside[(k + 1) % 3] ? 1.0 : segment_fraction_in_ball(p[k], p[(k + 1) % 3], c, r);
      if (!(fraction > 0)) continue;
      sums.tensor.add(fraction * g.beta_per_length[e], tri.side(k));
      for (int32_t other : g.topo.edges[e].face)
        if (other >= 0 && s.first_visit(s.face_mark, uint32_t(other))) s.queue.push_back(uint32_t(other));
    }
  }
  return sums;
}

struct Frame {
  glm::dvec3 normal, d_min, d_max;
  double k_min, k_max;
};

// T restricted to the tangent plane of n: the larger eigenvalue is k_max and its
// eigenvector d_min (the roles swap, see curvature.hpp).
Frame tangent_plane_frame(const SymmetricTensor& t, const glm::dvec3& n) {
  glm::dvec3 t1, t2;
  tangent_basis(n, t1, t2);
  double a = glm::dot(t1, t.apply(t1)), b = glm::dot(t1, t.apply(t2)), d = glm::dot(t2, t.apply(t2));
  double mean = 0.5 * (a + d), deviation = std::hypot(0.5 * (a - d), b);
  double theta = 0.5 * std::atan2(2 * b, a - d);  // eigenvector of the larger eigenvalue
  glm::dvec3 larger = std::cos(theta) * t1 + std::sin(theta) * t2;
  return {n, larger, glm::cross(n, larger), mean - deviation, mean + deviation};
}

// SPEC's literal reading: the eigenvector of the smallest-magnitude eigenvalue is the
// normal. Where that eigenvalue ties with another (the umbilic test's tolerance: a
// cylinder's normal and circumferential direction both have ~0, a plane all three), the
// eigenvectors are any basis of their eigenspace, so n is the ball normal projected into
// that eigenspace.
glm::dvec3 tensor_normal(const SymmetricTensor& t, const glm::dvec3& ball_normal, double ratio, double flat) {
  Eigen::Matrix3d m;
  m << t.xx, t.xy, t.xz, t.xy, t.yy, t.yz, t.xz, t.yz, t.zz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
  Eigen::Vector3d magnitude = eig.eigenvalues().cwiseAbs();
  double tie = ratio * magnitude.maxCoeff() + flat;
  glm::dvec3 n(0);
  for (int i = 0; i < 3; ++i) {
    if (magnitude[i] > magnitude.minCoeff() + tie) continue;
    glm::dvec3 e(eig.eigenvectors()(0, i), eig.eigenvectors()(1, i), eig.eigenvectors()(2, i));
    n += glm::dot(ball_normal, e) * e;
  }
  return glm::length(n) > 1e-6 ? glm::normalize(n) : ball_normal;
}

// T / |B| and its frame; `flat`: curvatures below it count as zero.
Frame vertex_frame(const BallSums& sums, const glm::dvec3& mesh_normal, const CurvatureParams& p, double flat) {
  glm::dvec3 n = unit_or_zero(sums.normal);
  if (n == glm::dvec3(0)) n = mesh_normal;
  SymmetricTensor t = sums.tensor;
  double inverse_area = sums.area > 0 ? 1.0 / sums.area : 0.0;
  for (double* x : {&t.xx, &t.xy, &t.xz, &t.yy, &t.yz, &t.zz}) *x *= inverse_area;
  if (p.normal == CurvatureNormal::Tensor) n = tensor_normal(t, n, p.umbilic_ratio, flat);
  return tangent_plane_frame(t, n);
}

double ring_radius(uint32_t v, const Mesh& mesh, const MeshTopology& topo) {
  double r = 0;
  for (uint32_t u : topo.neighbors_of(v))
    r = std::max(r, glm::length(glm::dvec3(mesh.positions[u]) - glm::dvec3(mesh.positions[v])));
  return r;
}

}  // namespace

Curvature tensor_curvature(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress) {
  const Surface g{mesh, topo, edge_beta_per_length(mesh, topo)};
  const double radius = double(p.radius) * double(mesh.bbox_diagonal());
  const double flat = double(p.flat_curvature) / std::max(double(mesh.bbox_diagonal()), 1e-30);
  const size_t n = mesh.positions.size();
  Curvature c;
  assign_populated(c.k_min, n), assign_populated(c.k_max, n);
  for (auto* v : {&c.normal, &c.d_min, &c.d_max}) assign_populated(*v, n);
  const bool ball = p.radius > 0;
  tbb::enumerable_thread_specific<Scratch> scratch(ball ? mesh.triangles.size() : 0, ball ? topo.edges.size() : 0);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(n), 1024), [&](const tbb::blocked_range<uint32_t>& range) {
    Scratch& s = scratch.local();
    for (uint32_t v = range.begin(); v != range.end(); ++v) {
      s.next_vertex();
      bool ring = !ball || (p.ring_fallback && radius < ring_radius(v, mesh, topo));
      BallSums sums = ring ? one_ring_sums(v, g, s) : ball_sums(v, radius, g, s);
      Frame f = vertex_frame(sums, glm::dvec3(mesh.normals[v]), p, flat);
      c.normal[v] = f.normal, c.d_min[v] = f.d_min, c.d_max[v] = f.d_max;
      c.k_min[v] = float(f.k_min), c.k_max[v] = float(f.k_max);
    }
    progress.advance(range.size());
  });
  return c;
}

}  // namespace curvature

Curvature estimate_curvature(const Mesh& input, const CurvatureParams& p, bool show_progress) {
  Mesh with_normals;
  const Mesh* mesh = &input;
  if (input.normals.size() != input.positions.size()) {
    with_normals = input;
    compute_normals(with_normals);
    mesh = &with_normals;
  }
  MeshTopology topo = build_topology(*mesh);
  bool tensor = p.method == CurvatureMethod::Tensor;
  Progress progress(tensor ? "curvature (tensor)" : "curvature (jet)", mesh->positions.size(), show_progress);
  Curvature c = tensor ? curvature::tensor_curvature(*mesh, topo, p, progress)
                       : curvature::jet_curvature(*mesh, topo, p, progress);
  curvature::propagate_directions(topo, p, mesh->bbox_diagonal(), c);
  return c;
}

}  // namespace plumbago
