// Mesh loading (common/mesh/mesh_io.cpp): the shared models, welding, refusals with the file
// and line, degenerate but valid input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "common/mesh/mesh.hpp"
#include "common/util/memory_budget.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/test_scenes.hpp"

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
    if (forward && backward)
      ++shared, ++consistent;
    else if (n > 1)
      ++shared;
  }
  return shared ? double(consistent) / double(shared) : 0.0;
}

// Counts after welding: the faces are the files' own counts (../shared/models/README.md);
// the vertices too, except where a file repeats positions (teapot 3644 -> 3241 distinct
// positions, ogre 62194 -> 62185).
TEST(MeshIo, SharedModelsHaveTheirCountsAndFiniteUnitNormals) {
  PLUMBAGO_REQUIRE_MODEL("fandisk.obj");
  std::string missing;
  struct Expected {
    const char* name;
    size_t vertices, faces;
  };
  for (const auto& e :
       {Expected{"fandisk.obj", 6475, 12946}, Expected{"stanford-bunny.obj", 35947, 69451},
        Expected{"teapot.obj", 3241, 6320}, Expected{"ogre.obj", 62185, 124008},
        Expected{"rocker-arm.obj", 10044, 20088}, Expected{"spot.obj", 2930, 5856}, Expected{"cow.obj", 2903, 5804}}) {
    if (!testing::have_model(e.name)) {
      missing += std::string(missing.empty() ? "" : ", ") + "../shared/models/" + e.name;
      continue;
    }
    Mesh m = load_mesh(testing::model_path(e.name));
    EXPECT_EQ(m.positions.size(), e.vertices) << e.name;
    EXPECT_EQ(m.triangles.size(), e.faces) << e.name;
    expect_unit_finite_normals(m);
  }
  if (!missing.empty()) GTEST_SKIP() << "shared models not here, not checked: " << missing << " absent";
}

TEST(MeshIo, IgeaTriangleStripsAreDecodedWithOneOrientation) {
  PLUMBAGO_REQUIRE_MODEL("igea.ply");
  Mesh m = load_mesh(testing::model_path("igea.ply"));
  std::printf("[igea] %zu vertices, %zu triangles\n", m.positions.size(), m.triangles.size());
  EXPECT_EQ(m.positions.size(), 134345u);
  EXPECT_GT(m.triangles.size(), 2 * m.positions.size() * 9 / 10);
  EXPECT_GT(consistent_orientation_share(m), 0.99);
  expect_unit_finite_normals(m);
  // Facing outward: the bust is nearly closed, so the volume it encloses is positive.
  glm::vec3 c = (m.bbox_min() + m.bbox_max()) * 0.5f;
  double volume = 0;
  for (const auto& t : m.triangles)
    volume += glm::dot(m.positions[t[0]] - c, glm::cross(m.positions[t[1]] - c, m.positions[t[2]] - c)) / 6.0;
  EXPECT_GT(volume, 0.0);
}

// The cube's 12 triangles as STL, which stores every corner of every facet: 36 corners.
std::string ascii_stl_cube(const float (&c)[8][3], const int (&f)[12][3]) {
  std::string stl = "solid cube\n";
  for (const auto& t : f) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k)
      stl += "vertex " + std::to_string(c[t[k]][0]) + " " + std::to_string(c[t[k]][1]) + " " +
             std::to_string(c[t[k]][2]) + "\n";
    stl += "endloop\nendfacet\n";
  }
  return stl + "endsolid cube\n";
}

std::string binary_stl_cube(const float (&c)[8][3], const int (&f)[12][3]) {
  std::string stl(80, ' ');
  auto put = [&](const void* p, size_t n) { stl.append(static_cast<const char*>(p), n); };
  uint32_t count = 12;
  put(&count, 4);
  for (const auto& t : f) {
    const float normal[3] = {0, 0, 0};
    put(normal, 12);
    for (int k = 0; k < 3; ++k) put(c[t[k]], 12);
    stl += std::string(2, '\0');
  }
  return stl;
}

TEST(MeshIo, StlCubeIsWelded) {
  TempDir tmp;
  const float c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  for (const auto& [name, text] :
       {std::pair{"ascii.stl", ascii_stl_cube(c, f)}, std::pair{"binary.stl", binary_stl_cube(c, f)}}) {
    Mesh m = load_mesh(tmp.write(name, text));
    EXPECT_EQ(m.positions.size(), 8u) << name;
    EXPECT_EQ(m.triangles.size(), 12u) << name;
    EXPECT_NEAR(consistent_orientation_share(m), 1.0, 1e-12) << name;
    for (size_t v = 0; v < 8; ++v)  // a corner's normal points away from the cube's center
      EXPECT_GT(glm::dot(m.normals[v], m.positions[v] - glm::vec3(0.5f)), 0.5f) << name;
  }
}

void expect_refused(const std::string& path, std::initializer_list<std::string> needles) {
  try {
    load_mesh(path);
    FAIL() << path << " was accepted";
  } catch (const MeshError& e) {
    for (const auto& n : needles) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
  }
}

const char* kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(MeshIo, RefusalsNameTheFileAndLine) {
  TempDir tmp;
  std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_refused(tmp.path("missing.obj"), {"missing.obj", "no such"});
  expect_refused(tmp.write("model.xyz", "1 2 3\n"), {"model.xyz", "unknown mesh format"});
  expect_refused(tmp.write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n"), {"nan.obj:3:", "finite"});
  expect_refused(tmp.write("inf.obj", "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n"), {"inf.obj:2:"});
  expect_refused(tmp.write("huge.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"), {"huge.obj:2:", "1e39"});
  expect_refused(tmp.write("word.obj", "v 0 0 0\nv 1 0 zero\nv 0 1 0\nf 1 2 3\n"), {"word.obj:2:", "'zero'"});
  expect_refused(tmp.write("short.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n"), {"short.obj:2:"});
  expect_refused(tmp.write("range.obj", tri + "f 1 2 3\nf 1 2 9\n"), {"range.obj:5:", "face index 9"});
  expect_refused(tmp.write("zero.obj", tri + "f 0 1 2\n"), {"zero.obj:4:", "face index 0"});
  expect_refused(tmp.write("back.obj", "v 0 0 0\nv 1 0 0\nf -3 -2 -1\nv 0 1 0\n"), {"back.obj:3:", "face index -3"});
  expect_refused(tmp.write("nofaces.obj", "v 0 0 0\nv 1 0 0\n"), {"nofaces.obj", "no faces"});
  expect_refused(tmp.write("empty.stl", ""), {"empty.stl"});
  expect_refused(tmp.write("garbage.ply", "this is not a ply file\n"), {"garbage.ply", "not a PLY file"});
  expect_refused(tmp.write("nan.ply", std::string(kPlyHeader) + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"),
                 {"nan.ply:11:", "vertex 1", "NaN"});
  expect_refused(tmp.write("range.ply", std::string(kPlyHeader) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                 {"range.ply:13:", "face 0", "index 7"});
  expect_refused(tmp.write("short.ply", std::string(kPlyHeader) + "0 0 0\n1 0 0\n"), {"short.ply", "ends early"});
  expect_refused(tmp.write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                 {"range.off:6:", "face index 7"});
  expect_refused(tmp.write("short.off", "OFF\n99999999999 1 0\n0 0 0\n"), {"short.off", "ends early"});
  expect_refused(tmp.write("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"), {"nan.off:4:", "'nan'"});
}

// Binary PLY in both byte orders; a face index out of range is named by its face.
TEST(MeshIo, BinaryPlyInBothByteOrders) {
  TempDir tmp;
  for (const char* order : {"binary_little_endian", "binary_big_endian"})
    for (int last : {3, 9}) {
      std::string ply = std::string("ply\nformat ") + order +
                        " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                        "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
      bool big = std::string(order) == "binary_big_endian";
      auto put = [&](const void* p, size_t n) {
        std::string bytes(static_cast<const char*>(p), n);
        if (big) std::reverse(bytes.begin(), bytes.end());
        ply += bytes;
      };
      for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f}) put(&v, 4);
      for (const auto& face : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{1, last, 2}}) {
        ply += char(3);
        for (int i : face) put(&i, 4);
      }
      std::string path = tmp.write(std::string(order) + ".ply", ply);
      if (last == 9) {
        expect_refused(path, {order, "face 1", "index 9"});
      } else {
        Mesh m = load_mesh(path);
        EXPECT_EQ(m.positions.size(), 4u) << order;
        EXPECT_EQ(m.triangles.size(), 2u) << order;
        EXPECT_EQ(m.positions[3], glm::vec3(1, 1, 0)) << order;
      }
    }
}

TEST(MeshIo, DegenerateButValidInputLoadsWithoutNaN) {
  TempDir tmp;
  // A zero-area triangle (three collinear points), an isolated vertex, a duplicated vertex.
  std::string obj = "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 5 5 5\nv 1 0 0\nf 1 2 3\nf 1 6 4\n";
  Mesh m = load_mesh(tmp.write("degenerate.obj", obj));
  expect_unit_finite_normals(m);
  EXPECT_EQ(m.triangles.size(), 2u);
}

TEST(MeshIo, ValidIndexFormsAreAccepted) {
  TempDir tmp;
  // Negative OBJ indices count back from the last vertex; v/vt/vn corners; a quad.
  Mesh m = load_mesh(tmp.write("forms.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 1 1 0\nf 2/1/1 4/1/1 3/1/1\n"));
  EXPECT_EQ(m.triangles.size(), 2u);
  m = load_mesh(tmp.write("quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
  EXPECT_EQ(m.triangles.size(), 2u);
  expect_unit_finite_normals(m);
}

// The memory budget for the duration of a test.
class BudgetOf {
 public:
  explicit BudgetOf(double gb) { set_memory_budget_gb(gb); }
  ~BudgetOf() { set_memory_budget_gb(kDefaultMemoryBudgetGb); }
};

// Every format's counts go through the budget before the mesh is made: a tetrahedron
// (4 vertices, 4 triangles: about 6 kB by mesh_bytes) is refused under 1 kB.
TEST(MeshIo, MeshesOverTheMemoryBudgetAreRefused) {
  const std::string corpus = std::string(PLUMBAGO_SOURCE_DIR) + "/tests/corpus/mesh/";
  const char* files[] = {"obj_ok_tetra.obj",     "off_ok_tetra.off", "ply_ascii_ok.ply",
                         "ply_binary_le_ok.ply", "stl_ascii_ok.stl", "stl_binary_ok.stl"};
  {
    BudgetOf tiny(1e-6);
    for (const char* name : files) expect_refused(corpus + name, {name, "would need", "over the memory budget of"});
  }
  for (const char* name : files) EXPECT_EQ(load_mesh(corpus + name).triangles.size(), 4u) << name;
}

}  // namespace
}  // namespace plumbago
