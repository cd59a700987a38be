// The curvature tensor of Cohen-Steiner & Morvan (Alliez et al. 2003, §3; Lee et al. 2006, §5.3).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

#include "common/core/preprocess.hpp"
#include "common/curvature/curvature_internal.hpp"
#include "common/curvature/curvature_memory.hpp"
#include "common/sketchy/sketchy.hpp"

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

// The literal reading (Alliez et al. 2003): the eigenvector of the smallest-magnitude eigenvalue is the
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

}  // namespace

Curvature tensor_curvature(const Mesh& mesh, const MeshTopology& topo, const CurvatureParams& p, Progress& progress) {
  const double flat = double(p.flat_curvature) / std::max(double(mesh.bbox_diagonal()), 1e-30);
  const size_t n = mesh.positions.size();
  Curvature c;
  assign_populated(c.k_min, n), assign_populated(c.k_max, n);
  for (auto* v : {&c.normal, &c.d_min, &c.d_max}) assign_populated(*v, n);
  for_each_vertex_sums(mesh, topo, p, progress, [&](uint32_t v, const BallSums& sums) {
    Frame f = vertex_frame(sums, glm::dvec3(mesh.normals[v]), p, flat);
    c.normal[v] = f.normal, c.d_min[v] = f.d_min, c.d_max[v] = f.d_max;
    c.k_min[v] = float(f.k_min), c.k_max[v] = float(f.k_max);
  });
  return c;
}

}  // namespace curvature

double folded_face_share(const Mesh& mesh) {
  if (mesh.triangles.empty()) return 0.0;
  std::vector<glm::dvec3> corner_normal(mesh.positions.size(), glm::dvec3(0)), face_normal(mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    face_normal[f] = glm::cross(b - a, c - a);
    for (int k = 0; k < 3; ++k) corner_normal[t[k]] += face_normal[f];
  }
  size_t folded = 0;
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (glm::dot(face_normal[f], corner_normal[mesh.triangles[f][k]]) < 0) {
        ++folded;
        break;
      }
  return double(folded) / double(mesh.triangles.size());
}

CurvatureMethod resolved_method(const Mesh& mesh, const CurvatureParams& p) {
  if (p.method != CurvatureMethod::Auto) return p.method;
  return folded_face_share(mesh) > double(p.auto_fold_share) ? CurvatureMethod::Jet : CurvatureMethod::Tensor;
}

const char* method_name(CurvatureMethod method) {
  switch (method) {
    case CurvatureMethod::Auto:
      return "auto";
    case CurvatureMethod::Tensor:
      return "tensor";
    case CurvatureMethod::Jet:
      return "jet";
  }
  return "?";
}

Curvature estimate_curvature(const Mesh& input, const CurvatureParams& p, bool show_progress) {
  Mesh with_normals;
  const Mesh* mesh = &input;
  if (input.normals.size() != input.positions.size()) {
    with_normals = input;
    compute_normals(with_normals);
    mesh = &with_normals;
  }
  MeshTopology topo = build_topology(*mesh);
  bool tensor = resolved_method(*mesh, p) == CurvatureMethod::Tensor;
  Progress progress(tensor ? "curvature (tensor)" : "curvature (jet)", mesh->positions.size(), show_progress);
  Curvature c = tensor ? curvature::tensor_curvature(*mesh, topo, p, progress)
                       : curvature::jet_curvature(*mesh, topo, p, progress);
  curvature::propagate_directions(topo, p, mesh->bbox_diagonal(), c);
  return c;
}

void CurvatureStage::make(const Scene& scene, Preprocessed& out) {
  auto params = scene.params.get<CurvatureParams>();
  CurvatureOptions options;
  options.progress = false;
  std::vector<Curvature> per_object;
  for (const auto& obj : ordinary_objects(scene).objects)  // the G-buffer's objects
    per_object.push_back(compute_curvature(*obj.mesh, params, options));
  out.put(kCurvature, std::move(per_object));
}

}  // namespace plumbago
