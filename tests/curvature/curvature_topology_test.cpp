// The adjacency the curvature reads (common/mesh/mesh_topology.hpp): the parallel construction
// of manifold meshes gives the same faces, neighbors and edges as OpenMesh's, up to the
// numbering of the edges, and every other mesh goes through OpenMesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <random>

#include "common/mesh/mesh_topology.hpp"
#include "tests/support/analytic_surfaces.hpp"

namespace plumbago {
namespace {

using namespace plumbago::testing;

// Same lists per vertex, same split faces, and edge e of a face in `a` is the edge in
// the same place in `b` with the same ends and faces, one to one.
void expect_same_topology(const Mesh& mesh, const MeshTopology& a, const MeshTopology& b, const std::string& name) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count()) << name;
  for (uint32_t v = 0; v < a.vertex_count(); ++v) {
    ASSERT_TRUE(std::ranges::equal(a.faces_of(v), b.faces_of(v))) << name << " vertex " << v;
    ASSERT_TRUE(std::ranges::equal(a.neighbors_of(v), b.neighbors_of(v))) << name << " vertex " << v;
  }
  EXPECT_EQ(a.split_faces, b.split_faces) << name;
  ASSERT_EQ(a.edges.size(), b.edges.size()) << name;
  std::vector<int64_t> b_of_a(a.edges.size(), -1);
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      uint32_t ea = a.face_edges[f][k], eb = b.face_edges[f][k];
      ASSERT_EQ(a.edges[ea], b.edges[eb]) << name << " face " << f << " corner " << k;
      ASSERT_TRUE(b_of_a[ea] < 0 || b_of_a[ea] == eb) << name << " face " << f;
      b_of_a[ea] = eb;
    }
  EXPECT_EQ(std::count(b_of_a.begin(), b_of_a.end(), -1), 0) << name << ": an edge of no face";
}

// Only the parallel construction numbers the edges by their lower vertex.
bool numbered_by_lower_vertex(const MeshTopology& topo) {
  return std::is_sorted(topo.edges.begin(), topo.edges.end(),
                        [](const auto& a, const auto& b) { return std::min(a.from, a.to) < std::min(b.from, b.to); });
}

// Returns whether build_topology took the parallel path.
bool expect_same_as_openmesh(const Mesh& mesh, const std::string& name) {
  MeshTopology topo = build_topology(mesh);
  expect_same_topology(mesh, topo, build_topology_with_openmesh(mesh), name);
  return numbered_by_lower_vertex(topo) && !numbered_by_lower_vertex(build_topology_with_openmesh(mesh));
}

Mesh shuffled_faces(Mesh m) {
  std::shuffle(m.triangles.begin(), m.triangles.end(), std::mt19937(7));
  return m;
}

TEST(Topology, ManifoldMeshesMatchOpenMesh) {
  Mesh sphere = analytic_sphere(1.0, 0.15, Meshing::Irregular).mesh;
  EXPECT_TRUE(expect_same_as_openmesh(sphere, "irregular sphere"));
  EXPECT_TRUE(expect_same_as_openmesh(shuffled_faces(sphere), "sphere with shuffled faces"));
  EXPECT_TRUE(expect_same_as_openmesh(analytic_torus(1.0, 0.4, 0.1, Meshing::Regular).mesh, "regular torus"));
  EXPECT_TRUE(expect_same_as_openmesh(analytic_saddle(0.5, 0.1, Meshing::Irregular).mesh, "saddle (boundary)"));
  EXPECT_TRUE(expect_same_as_openmesh(analytic_cylinder(0.5, 1.0, 0.08, Meshing::Irregular).mesh, "open cylinder"));
  EXPECT_TRUE(expect_same_as_openmesh(schwarz_lantern(1.0, 1.0, 6, 400), "Schwarz lantern"));
  EXPECT_TRUE(expect_same_as_openmesh(subdivided_cube(4), "cube"));
  Mesh pillow;  // two triangles glued along all three edges: every vertex a closed fan of two
  pillow.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  pillow.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_TRUE(expect_same_as_openmesh(pillow, "pillow"));
}

// The benchmark's models take the parallel path; the teapot's seams do not.
TEST(Topology, SharedModelsMatchOpenMesh) {
  std::string missing;
  for (auto [name, manifold] : {std::pair{"fandisk.obj", true},
                                {"stanford-bunny.obj", true},
                                {"ogre.obj", true},
                                {"teapot.obj", false},
                                {"igea.ply", true}}) {
    std::string path = std::string(PLUMBAGO_MODELS_DIR) + "/" + name;
    if (!std::filesystem::exists(path)) {
      missing += std::string(missing.empty() ? "" : ", ") + "../shared/models/" + name;
      continue;
    }
    EXPECT_EQ(expect_same_as_openmesh(load_mesh(path), name), manifold) << name;
  }
  if (!missing.empty()) GTEST_SKIP() << "shared models not here, not checked: " << missing << " absent";
}

// Each of these makes build_topology fall back to OpenMesh, which splits the odd face
// off; the result is OpenMesh's own.
TEST(Topology, NonManifoldInputIsSplitAsOpenMeshDoes) {
  Mesh sphere = analytic_sphere(1.0, 0.3, Meshing::Irregular).mesh;
  const auto t = sphere.triangles[0];
  uint32_t apex = uint32_t(sphere.positions.size());
  Mesh third_face = sphere, flipped = sphere, repeated = sphere, bowtie;
  third_face.positions.push_back(2.0f * sphere.positions[t[0]]);
  third_face.triangles.push_back({t[0], t[1], apex});
  flipped.triangles[3] = {flipped.triangles[3][0], flipped.triangles[3][2], flipped.triangles[3][1]};
  repeated.triangles.push_back({t[1], t[1], t[2]});
  bowtie.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};  // two fans at vertex 0
  bowtie.triangles = {{0, 1, 2}, {0, 3, 4}};
  Mesh closed_then_more = sphere;  // a face at a vertex whose fan is already closed
  closed_then_more.positions.push_back(3.0f * sphere.positions[t[0]]);
  closed_then_more.positions.push_back(3.0f * sphere.positions[t[1]]);
  closed_then_more.triangles.push_back({t[0], apex, apex + 1});
  for (auto& [name, mesh] : std::map<std::string, Mesh*>{{"third face on an edge", &third_face},
                                                         {"flipped face", &flipped},
                                                         {"repeated corner", &repeated},
                                                         {"face at a closed fan", &closed_then_more}}) {
    MeshTopology topo = build_topology(*mesh);
    EXPECT_GT(topo.split_faces, 0u) << name;
    expect_same_topology(*mesh, topo, build_topology_with_openmesh(*mesh), name);
  }
  MeshTopology topo = build_topology(bowtie);  // OpenMesh keeps both fans, splits nothing
  EXPECT_EQ(topo.split_faces, 0u);
  expect_same_topology(bowtie, topo, build_topology_with_openmesh(bowtie), "bowtie");
}

}  // namespace
}  // namespace plumbago
