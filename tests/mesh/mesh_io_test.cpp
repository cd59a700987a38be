// Mesh loading (common/mesh/mesh_io.cpp): the shared models, welding, refusals with the file
// and line, degenerate but valid input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "common/mesh/mesh.hpp"
#include "common/mesh/mesh_formats.hpp"
#include "common/mesh/procedural.hpp"
#include "common/util/input_file.hpp"
#include "common/util/memory_budget.hpp"
#include "tests/support/far_mesh_files.hpp"
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
    // The weld after centering in double (center_and_weld) merges no vertex that the
    // exact weld in the file's float coordinates kept (the expected counts are its).
    std::printf(
        "[model] %s: %zu vertices (exact weld: %zu), %zu triangles (file: %zu); welded %zu, dropped %zu "
        "degenerate and %zu duplicate faces\n",
        e.name, m.positions.size(), e.vertices, m.triangles.size(), e.faces, m.cleanup.merged_vertices,
        m.cleanup.degenerate_faces, m.cleanup.duplicate_faces);
    EXPECT_EQ(m.positions.size(), e.vertices) << e.name;
    EXPECT_EQ(m.triangles.size(), e.faces) << e.name;
    expect_unit_finite_normals(m);
  }
  if (!missing.empty()) GTEST_SKIP() << "shared models not here, not checked: " << missing << " absent";
}

TEST(MeshIo, IgeaTriangleStripsAreDecodedWithOneOrientation) {
  PLUMBAGO_REQUIRE_MODEL("igea.ply");
  Mesh m = load_mesh(testing::model_path("igea.ply"));
  std::printf("[igea] %zu vertices, %zu triangles; welded %zu, dropped %zu degenerate and %zu duplicate faces\n",
              m.positions.size(), m.triangles.size(), m.cleanup.merged_vertices, m.cleanup.degenerate_faces,
              m.cleanup.duplicate_faces);
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
      EXPECT_GT(glm::dot(m.normals[v], glm::vec3(m.origin + glm::dvec3(m.positions[v])) - glm::vec3(0.5f)), 0.5f)
          << name;
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
        EXPECT_EQ(m.origin + glm::dvec3(m.positions[3]), glm::dvec3(1, 1, 0)) << order;
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

// OBJ texture coordinates become the mesh's per-corner (u, v) when every face names ones the
// file has; a dropped face takes its own with it; otherwise the mesh has none.
TEST(MeshIo, ObjTextureCoordinatesFollowTheirFaces) {
  TempDir tmp;
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0 0.5\n";
  Mesh m = load_mesh(tmp.write("uv.obj", quad + "f 1/1 1/2 3/3\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"));
  ASSERT_EQ(m.triangles.size(), 2u) << "the degenerate face is dropped";
  ASSERT_EQ(m.uvs.size(), 6u);
  for (int k = 0; k < 3; ++k) {
    glm::vec3 p0 = m.positions[m.triangles[0][k]], p1 = m.positions[m.triangles[1][k]];
    EXPECT_EQ(m.uvs[size_t(k)], glm::vec2(p0.x + 0.5f, p0.y + 0.5f) * 0.5f);  // centered on (0.5, 0.5)
    EXPECT_EQ(m.uvs[3 + size_t(k)], glm::vec2(p1.x + 0.5f, p1.y + 0.5f) * 0.5f);
  }
  EXPECT_TRUE(load_mesh(tmp.write("some.obj", quad + "f 1/1 2/2 3/3\nf 1 3 4\n")).uvs.empty());
  EXPECT_TRUE(load_mesh(tmp.write("dangling.obj", quad + "f 1/1 2/2 3/9\n")).uvs.empty());
  expect_refused(tmp.write("nanuv.obj", quad + "vt 0 nan\nf 1/1 2/2 3/3\n"), {"nanuv.obj:9:", "texture coordinate"});
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

// A sphere's file at 1e6 and 1e7, in every text format, reads as the file at 0: the same
// vertices and faces, the same centered positions to the bit; Mesh::origin holds the
// offset. Before, the files were read (OpenMesh, the OFF and STL readers) and welded in
// float: at 1e7 float resolves 1, and the unit sphere became a box of a few vertices.
TEST(MeshIo, FilesFarFromTheOriginReadAsAtZero) {
  TempDir tmp;
  const Mesh sphere = make_procedural("sphere");
  for (const std::string& format : testing::text_mesh_formats()) {
    const Mesh zero = load_mesh(tmp.write("zero." + format, testing::mesh_text_at(sphere, format, 0)));
    EXPECT_EQ(zero.positions.size(), sphere.positions.size()) << format;
    for (double offset : {1e6, 1e7}) {
      const Mesh far = load_mesh(tmp.write("far." + format, testing::mesh_text_at(sphere, format, offset)));
      std::printf("[far %s %g] %zu vertices, %zu triangles (at 0: %zu, %zu)\n", format.c_str(), offset,
                  far.positions.size(), far.triangles.size(), zero.positions.size(), zero.triangles.size());
      ASSERT_EQ(far.positions.size(), zero.positions.size()) << format << " " << offset;
      ASSERT_EQ(far.triangles, zero.triangles) << format << " " << offset;
      EXPECT_EQ(far.positions, zero.positions) << format << " " << offset;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(far.origin[c] - zero.origin[c], offset, 1e-9) << format;
    }
  }
}

// The weld's tolerance is relative to the object's size: two vertices 1e-9 of its size
// apart are one, 1e-5 apart are two, whatever the size (1e-6 to 1e6) and wherever it lies.
TEST(MeshIo, WeldToleranceIsRelativeToTheObjectsSize) {
  for (double size : {std::ldexp(1.0, -20), 1.0, std::ldexp(1.0, 20)})  // the pair on a float, not between two
    for (double at : {0.0, 1e6}) {
      if (size * 1e-5 < at * 1e-15) continue;  // double itself does not hold them apart there
      for (double apart : {1e-9, 1e-5}) {
        MeshFile f;
        f.name = "test";
        auto p = [&](double x, double y) { return glm::dvec3(at + size * x, at + size * y, at); };
        f.positions = {p(0, 0), p(1, 0), p(0, 1), p(0.25, 0.75), p(0.25 + apart, 0.75)};
        f.triangles = {{0, 1, 3}, {0, 4, 2}};
        Mesh m = center_and_weld(f);
        EXPECT_EQ(m.positions.size(), apart < 1e-6 ? 4u : 5u) << size << " at " << at << " apart " << apart;
        EXPECT_EQ(m.cleanup.merged_vertices, apart < 1e-6 ? 1u : 0u);
      }
    }
}

// Issue 32: a stroke object whose mesh repeated one face 200,000 times took several GB
// and over a minute. Faces with the same corners in the same cyclic order are dropped when
// the mesh is read (and counted); the opposite order is kept: a two-sided sheet is valid.
TEST(MeshIo, DuplicateFacesAreDroppedWhenRead) {
  TempDir tmp;
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const int repeats = 200000;
  for (int i = 0; i < repeats; ++i) obj += i % 3 == 0 ? "f 2 3 4\n" : i % 3 == 1 ? "f 3 4 2\n" : "f 4 2 3\n";
  obj += "f 2 4 3\nf 4 3 2\nf 1 1 2\nf 1 2 2\n";  // the opposite order (twice), two degenerate
  Mesh m = load_mesh(tmp.write("repeated.obj", obj));
  EXPECT_EQ(m.triangles.size(), 5u);
  EXPECT_EQ(m.cleanup.duplicate_faces, size_t(repeats) + 1);
  EXPECT_EQ(m.cleanup.degenerate_faces, 2u);
  EXPECT_EQ(m.positions.size(), 4u);
}

// A path the system would refuse as too long is refused naming it (shortened) and the
// limit, not with the system's "File name too long"; as for every input file.
TEST(MeshIo, PathsTooLongAreRefusedWithTheLimit) {
  const std::string name(300, 'a');
  expect_refused("/tmp/" + name + ".obj", {"/tmp/aaaa", "...", "304 bytes", "255", "NAME_MAX"});
  std::string deep;
  for (int i = 0; i < 30; ++i) deep += "/" + std::string(200, 'b');
  expect_refused(deep + ".obj", {"/bbbb", "bytes long, over the 4095", "PATH_MAX"});
  expect_refused("/tmp/" + name + "/m.obj", {"the folder name 'aaaa", "' in it is 300 bytes long", "NAME_MAX"});
  try {
    load_mesh("/tmp/" + name + ".obj");
  } catch (const MeshError& e) {
    EXPECT_EQ(std::string(e.what()).find("File name too long"), std::string::npos) << e.what();
    EXPECT_LT(std::string(e.what()).size(), 300u) << e.what();  // not the whole path
  }
  for (const char* what : {"stroke file", "stroke style file", "SVG drawing", "scene file"}) try {
      read_input_file("/tmp/" + name + ".json", what);
      ADD_FAILURE() << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("cannot read the " + std::string(what) + ": its file name is 305 bytes"),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("255"), std::string::npos) << e.what();
    }
}

// Beyond the coordinate bound a mesh's faces may all collapse even in double (a unit mesh
// at 1e17): the refusal names the bound, not "every face is degenerate".
TEST(MeshIo, FacesLostFarBeyondTheBoundNameTheBound) {
  TempDir tmp;
  const std::string e17 = "100000000000000000", e17_1 = "100000000000000001";  // one double
  expect_refused(tmp.write("far.obj", "v " + e17 + " " + e17 + " " + e17 + "\nv " + e17_1 + " " + e17 + " " + e17 +
                                          "\nv " + e17 + " " + e17_1 + " " + e17 + "\nf 1 2 3\n"),
                 {"far.obj", "lies at (1e+17, 1e+17, 1e+17), beyond ±1e+09"});
  expect_refused(tmp.write("flat.obj", "v 0 0 0\nv 0 0 0\nv 1 0 0\nf 1 2 3\n"), {"every face is degenerate"});
}

}  // namespace
}  // namespace plumbago
