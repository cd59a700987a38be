// The ball grown with face clusters (common/curvature_clusters.hpp) has the same sums as
// the ball grown face by face, up to round-off, on irregular meshes, meshes with
// degenerate and non-manifold faces, and the shared models.
#include <gtest/gtest.h>

#include <filesystem>

#include "common/curvature_clusters.hpp"
#include "common/params.hpp"
#include "tests/analytic_surfaces.hpp"

namespace plumbago {
namespace {

using namespace plumbago::testing;
using curvature::BallSums;

std::vector<BallSums> all_sums(const Mesh& mesh, const MeshTopology& topo, float radius, bool clusters) {
  CurvatureParams p = ParamSet().get<CurvatureParams>();
  p.radius = radius;
  p.ring_fallback = false;
  Progress progress("test", mesh.positions.size(), false);
  std::vector<BallSums> sums(mesh.positions.size());
  curvature::for_each_vertex_sums(mesh, topo, p, clusters, progress,
                                  [&](uint32_t v, const BallSums& s) { sums[v] = s; });
  return sums;
}

double tensor_distance(const curvature::SymmetricTensor& a, const curvature::SymmetricTensor& b) {
  double d[] = {a.xx - b.xx, a.xy - b.xy, a.xz - b.xz, a.yy - b.yy, a.yz - b.yz, a.zz - b.zz};
  double sum = 0;
  for (double x : d) sum += x * x;
  return std::sqrt(sum);
}

// Area and normal to 1e-9 relative; the tensor to 1e-9 of |B| / diagonal (a curvature
// difference below 1e-9 / diagonal), which stays meaningful where T itself is ~0.
void expect_same_sums(const Mesh& mesh, float radius, const std::string& name) {
  MeshTopology topo = build_topology(mesh);
  auto with = all_sums(mesh, topo, radius, true), without = all_sums(mesh, topo, radius, false);
  const double diagonal = mesh.bbox_diagonal();
  size_t worst = 0;
  double worst_ratio = 0;
  for (size_t v = 0; v < with.size(); ++v) {
    double scale = 1e-9 * std::max(without[v].area, 1e-300);
    double ratio = std::max({std::abs(with[v].area - without[v].area) / scale,
                             glm::length(with[v].normal - without[v].normal) / scale,
                             tensor_distance(with[v].tensor, without[v].tensor) * diagonal / scale});
    if (ratio > worst_ratio) worst_ratio = ratio, worst = v;
  }
  EXPECT_LE(worst_ratio, 1.0) << name << ", radius " << radius << ": vertex " << worst << " is off by " << worst_ratio
                              << " x the tolerance (area " << with[worst].area << " vs " << without[worst].area << ")";
}

TEST(CurvatureClusters, SameSumsAsFaceByFaceOnIrregularMeshes) {
  Mesh torus = analytic_torus(1.0, 0.4, 0.03, Meshing::Irregular).mesh;
  for (float radius : {0.01f, 0.03f, 0.08f}) expect_same_sums(torus, radius, "irregular torus");
  expect_same_sums(analytic_saddle(0.5, 0.02, Meshing::Irregular).mesh, 0.05f, "irregular saddle (boundary)");
  expect_same_sums(analytic_cylinder(0.5, 1.0, 0.02, Meshing::Regular).mesh, 0.04f, "regular open cylinder");
  expect_same_sums(schwarz_lantern(1.0, 1.0, 6, 400), 0.05f, "Schwarz lantern");
}

TEST(CurvatureClusters, SameSumsAsFaceByFaceOnHardCases) {
  Mesh m = analytic_sphere(1.0, 0.05, Meshing::Irregular).mesh;
  const auto t = m.triangles[10];
  m.positions[t[0]] = m.positions[t[1]];  // a zero-length edge and a zero-area face
  const auto u = m.triangles[200];
  m.positions[u[2]] = 0.5f * (m.positions[u[0]] + m.positions[u[1]]);  // three corners on a line
  m.triangles.push_back({t[1], t[1], t[2]});                            // a repeated corner
  uint32_t apex = uint32_t(m.positions.size());
  m.positions.push_back(1.2f * m.positions[u[0]]);
  m.triangles.push_back({u[0], u[1], apex});  // a third face on an edge
  compute_normals(m);
  expect_same_sums(m, 0.05f, "sphere with degenerate and non-manifold faces");
  Mesh needles = analytic_saddle(0.5, 0.02, Meshing::Regular).mesh;
  for (auto& p : needles.positions) {
    int column = int(std::lround((p.x + 1) / 0.02));
    if (column % 4 == 1) p.x = -1 + 0.02f * float(column + 1) - 1e-6f;
  }
  compute_normals(needles);
  expect_same_sums(needles, 0.04f, "needle triangles");
}

TEST(CurvatureClusters, SameSumsAsFaceByFaceOnSharedModels) {
  for (const char* name : {"ogre.obj", "stanford-bunny.obj", "teapot.obj"}) {
    std::string path = std::string(PLUMBAGO_MODELS_DIR) + "/" + name;
    if (std::filesystem::exists(path)) expect_same_sums(load_mesh(path), 0.01f, name);
  }
}

// Every face in one level-1 cluster of at most 8, several levels on a large mesh, each
// parent's sphere around its children's, and the top clusters add up to the whole mesh.
TEST(CurvatureClusters, HierarchyNestsAndCoversTheMesh) {
  Mesh mesh = analytic_torus(1.0, 0.4, 0.02, Meshing::Irregular).mesh;
  MeshTopology topo = build_topology(mesh);
  auto h = curvature::build_face_clusters(mesh, topo, curvature::edge_beta_per_length(mesh, topo));
  std::vector<int> faces_per_cluster(h.nodes.size(), 0);
  for (uint32_t node : h.face_node) ++faces_per_cluster[node];
  double top_area = 0, mesh_area = 0;
  int levels = 1;
  for (size_t i = 0; i < h.nodes.size(); ++i) {
    EXPECT_LE(faces_per_cluster[i], 8);
    const auto& n = h.nodes[i];
    if (n.parent < 0) {
      top_area += n.sums.area;
      continue;
    }
    const auto& parent = h.nodes[size_t(n.parent)];
    EXPECT_LE(glm::length(n.center - parent.center) + n.radius, parent.radius * (1 + 1e-12)) << i;
  }
  for (int32_t node = int32_t(h.face_node[0]); h.nodes[size_t(node)].parent >= 0; node = h.nodes[size_t(node)].parent)
    ++levels;
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    mesh_area += 0.5 * glm::length(curvature::triangle(mesh, uint32_t(f)).twice_area_normal());
  EXPECT_GE(levels, 5);
  EXPECT_NEAR(top_area, mesh_area, 1e-9 * mesh_area);
}

}  // namespace
}  // namespace plumbago
