// Mesh loading (common/mesh_io.cpp): the shared models, welding, refusals with the file
// and line, degenerate but valid input.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "common/mesh.hpp"
#include "tests/temp_dir.hpp"
#include "tests/test_scenes.hpp"

namespace plumbago {
namespace {

using testing::TempDir;

void expect_unit_finite_normals(const Mesh& m) {
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const auto& n : m.normals) {
    ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
  }
}

// Share of interior edges whose two faces run along it in opposite directions.
double consistent_orientation_share(const Mesh& m) {
  std::map<std::pair<unsigned, unsigned>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) directed[{t[k], t[(k + 1) % 3]}]++;
  size_t shared = 0, consistent = 0;
  for (const auto& [e, n] : directed) {
    if (e.first > e.second) continue;
    bool forward = n > 0, backward = directed.count({e.second, e.first}) > 0;
    if (forward && backward) ++shared, ++consistent;
    else if (n > 1) ++shared;
  }
  return shared ? double(consistent) / double(shared) : 0.0;
}

TEST(MeshIo, FandiskHasItsPublishedCounts) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  Mesh m = load_mesh(testing::model_path("fandisk.obj"));
  EXPECT_EQ(m.positions.size(), 6475u);
  EXPECT_EQ(m.triangles.size(), 12946u);
  expect_unit_finite_normals(m);
}

TEST(MeshIo, EverySharedModelLoadsWithFiniteUnitNormals) {
  for (const char* name : {"stanford-bunny.obj", "teapot.obj", "ogre.obj", "cow.obj", "spot.obj", "rocker-arm.obj"}) {
    if (!testing::have_model(name)) continue;
    Mesh m = load_mesh(testing::model_path(name));
    EXPECT_GT(m.triangles.size(), 1000u) << name;
    expect_unit_finite_normals(m);
  }
}

TEST(MeshIo, TeapotKeepsItsNonManifoldFaces) {
  PLUMBAGO_REQUIRE_MODEL("teapot.obj");
  Mesh m = load_mesh(testing::model_path("teapot.obj"));
  EXPECT_EQ(m.triangles.size(), 6320u);  // none dropped by OpenMesh's complex-edge handling
}

TEST(MeshIo, IgeaTriangleStripsAreDecodedWithOneOrientation) {
  PLUMBAGO_REQUIRE_MODEL("igea.ply");
  Mesh m = load_mesh(testing::model_path("igea.ply"));
  std::printf("[igea] %zu vertices, %zu triangles\n", m.positions.size(), m.triangles.size());
  EXPECT_EQ(m.positions.size(), 134345u);
  EXPECT_GT(m.triangles.size(), 2 * m.positions.size() * 9 / 10);
  EXPECT_GT(consistent_orientation_share(m), 0.99);
  expect_unit_finite_normals(m);
}

TEST(MeshIo, StlCubeIsWelded) {
  TempDir tmp;
  std::string stl = "solid cube\n";
  const float c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  for (const auto& t : f) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k)
      stl += "vertex " + std::to_string(c[t[k]][0]) + " " + std::to_string(c[t[k]][1]) + " " +
             std::to_string(c[t[k]][2]) + "\n";
    stl += "endloop\nendfacet\n";
  }
  stl += "endsolid cube\n";
  Mesh m = load_mesh(tmp.write("cube.stl", stl));
  EXPECT_EQ(m.positions.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_NEAR(consistent_orientation_share(m), 1.0, 1e-12);
}

void expect_refused(const std::string& path, std::initializer_list<std::string> needles) {
  try {
    load_mesh(path);
    FAIL() << path << " was accepted";
  } catch (const MeshError& e) {
    for (const auto& n : needles) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
  }
}

TEST(MeshIo, RefusalsNameTheFileAndLine) {
  TempDir tmp;
  expect_refused(tmp.path("missing.obj"), {"missing.obj", "no such"});
  expect_refused(tmp.write("model.xyz", "1 2 3\n"), {"model.xyz", "unknown mesh format"});
  expect_refused(tmp.write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n"), {"nan.obj:3", "finite"});
  expect_refused(tmp.write("inf.obj", "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n"), {"inf.obj:2"});
  expect_refused(tmp.write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n"), {"range.obj:5", "9"});
  expect_refused(tmp.write("nofaces.obj", "v 0 0 0\nv 1 0 0\n"), {"nofaces.obj", "no faces"});
  expect_refused(tmp.write("garbage.ply", "this is not a ply file\n"), {"garbage.ply"});
  expect_refused(tmp.write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"), {"range.off"});
}

TEST(MeshIo, DegenerateButValidInputLoadsWithoutNaN) {
  TempDir tmp;
  // A zero-area triangle (three collinear points), an isolated vertex, a duplicated vertex.
  std::string obj = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 5 5 5\nv 1 0 0\nf 1 2 3\nf 1 6 4\n";
  Mesh m = load_mesh(tmp.write("degenerate.obj", obj));
  expect_unit_finite_normals(m);
  EXPECT_EQ(m.triangles.size(), 2u);
}

}  // namespace
}  // namespace plumbago
