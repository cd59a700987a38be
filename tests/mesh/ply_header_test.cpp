// Hostile mesh headers (common/mesh/ply_file.cpp, common/mesh/mesh_io.cpp): each refused with a
// MeshError naming the file and the header line or element, before OpenMesh sees the file
// (it crashes, loops forever or allocates without bound on these) and before anything is
// allocated for the counts. The test finishing at all is the check that nothing hangs;
// each refusal is also timed.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <limits>
#include <string>

#include "common/mesh/mesh.hpp"
#include "tests/support/temp_dir.hpp"

namespace plumbago {
namespace {

using testing::TempDir;

void expect_refused_quickly(const std::string& path, std::initializer_list<std::string> needles) {
  auto start = std::chrono::steady_clock::now();
  try {
    load_mesh(path);
    ADD_FAILURE() << path << " was accepted";
  } catch (const MeshError& e) {
    for (const auto& n : needles) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
  }
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0) << path;
}

const std::string kVertexFace =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\n";
const std::string kAscii = "ply\nformat ascii 1.0\n" + kVertexFace + "end_header\n";
const std::string kTriangle = "0 0 0\n1 0 0\n0 1 0\n";

TEST(PlyHeader, MalformedHeadersAreRefusedWithTheirLine) {
  TempDir tmp;
  // The four-line PLY that crashed OpenMesh.
  expect_refused_quickly(tmp.write("four.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
                         {"four.ply: line 3:", "'property' before any 'element'"});
  // No end_header: OpenMesh looped forever.
  expect_refused_quickly(tmp.write("noend.ply", "ply\nformat ascii 1.0\n" + kVertexFace + kTriangle + "3 0 1 2\n"),
                         {"noend.ply: line", "end_header"});
  expect_refused_quickly(tmp.write("vertex1.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"),
                         {"vertex1.ply: line 3:", "end_header"});
  // A header longer than 64 KiB without end_header.
  expect_refused_quickly(
      tmp.write("long.ply", "ply\nformat ascii 1.0\n" + kVertexFace + std::string(100000, 'c') + "\nend_header\n"),
      {"long.ply: line", "end_header", "65536"});
  // An element without properties: OpenMesh looped forever.
  expect_refused_quickly(tmp.write("noprops.ply",
                                   "ply\nformat ascii 1.0\nelement vertex 3\nelement face 1\n"
                                   "property list uchar int vertex_indices\nend_header\n" +
                                       kTriangle + "3 0 1 2\n"),
                         {"noprops.ply: line 3:", "element 'vertex' has no properties"});
  expect_refused_quickly(tmp.write("noprops2.ply", "ply\nformat ascii 1.0\n" + kVertexFace +
                                                       "element edge 0\nend_header\n" + kTriangle + "3 0 1 2\n"),
                         {"noprops2.ply: line 9:", "element 'edge' has no properties"});
  expect_refused_quickly(tmp.write("keyword.ply", "ply\nformat ascii 1.0\n" + kVertexFace + "bogus 1\nend_header\n"),
                         {"keyword.ply: line 9:", "unknown header keyword 'bogus'"});
  expect_refused_quickly(tmp.write("type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\n"),
                         {"type.ply: line 4:", "unknown property type 'quad'"});
  expect_refused_quickly(tmp.write("listcount.ply",
                                   "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                   "element face 1\nproperty list float int vertex_indices\n"),
                         {"listcount.ply: line 6:", "not an integer type"});
  expect_refused_quickly(
      tmp.write("format.ply", "ply\nformat binary_middle_endian 1.0\n" + kVertexFace + "end_header\n"),
      {"format.ply: line 2:", "binary_middle_endian"});
  expect_refused_quickly(tmp.write("version.ply", "ply\nformat ascii 2.0\n" + kVertexFace + "end_header\n"),
                         {"version.ply: line 2:", "'2.0'"});
  expect_refused_quickly(tmp.write("noformat.ply", "ply\n" + kVertexFace + "end_header\n"),
                         {"noformat.ply: line 2:", "'format'"});
  expect_refused_quickly(
      tmp.write("noface.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n"),
      {"noface.ply: line 5:", "no 'element face'"});
  expect_refused_quickly(tmp.write("novertex.ply",
                                   "ply\nformat ascii 1.0\nelement face 1\n"
                                   "property list uchar int vertex_indices\nend_header\n3 0 1 2\n"),
                         {"novertex.ply: line 5:", "no 'element vertex'"});
  expect_refused_quickly(tmp.write("negative.ply", "ply\nformat ascii 1.0\nelement vertex -3\n"),
                         {"negative.ply: line 3:", "negative count -3"});
  expect_refused_quickly(tmp.write("word.ply", "ply\nformat ascii 1.0\nelement vertex three\n"),
                         {"word.ply: line 3:", "'three' is not a count"});
  expect_refused_quickly(tmp.write("huge.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\n"),
                         {"huge.ply: line 3:", "out of range"});
  expect_refused_quickly(tmp.write("binary-junk.ply", std::string(200000, '\x01')),
                         {"binary-junk.ply", "not a PLY file"});
}

TEST(PlyHeader, CountsTheFileCannotHoldAreRefusedBeforeAllocating) {
  TempDir tmp;
  // Billions of elements of another kind: OpenMesh stayed busy for minutes.
  expect_refused_quickly(tmp.write("edges.ply", "ply\nformat ascii 1.0\n" + kVertexFace +
                                                    "element edge 4000000000\nproperty int vertex1\n"
                                                    "property int vertex2\nend_header\n" +
                                                    kTriangle + "3 0 1 2\n"),
                         {"edges.ply", "element edge claims 4000000000 records", "ends early"});
  std::string binary_edges = "ply\nformat binary_little_endian 1.0\n" + kVertexFace +
                             "element edge 4000000000\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  binary_edges += std::string(3 * 12 + 13, '\0');
  expect_refused_quickly(tmp.write("edges-bin.ply", binary_edges),
                         {"edges-bin.ply", "element edge claims 4000000000 records of at least 8 bytes",
                          "the file has 12 bytes left after the header and the elements before it"});
  // A binary vertex count beyond the file.
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  binary += std::string(1024, '\0');
  expect_refused_quickly(tmp.write("vertices.ply", binary),
                         {"vertices.ply: element vertex claims 4000000000 records of at least 12 bytes, "
                          "the file has 1024 bytes after the header"});
  // Just one record short, big-endian.
  std::string short_one =
      "ply\nformat binary_big_endian 1.0\n" + kVertexFace + "end_header\n" + std::string(3 * 12, '\0');
  expect_refused_quickly(tmp.write("short.ply", short_one), {"short.ply: element face claims 1 records"});
}

TEST(PlyHeader, BadFaceIndicesNeverReachAnUnsignedConversion) {
  TempDir tmp;
  int n = 0;
  for (const char* index : {"nan", "-1", "1.5", "3", "1e30", "-inf"}) {
    std::string name = "index" + std::to_string(n++) + ".ply";
    expect_refused_quickly(tmp.write(name, kAscii + kTriangle + "3 0 1 " + index + "\n"),
                           {name + ":13:", "face 0", "vertex index"});
  }
  expect_refused_quickly(tmp.write("nanlist.ply", kAscii + kTriangle + "nan 0 1 2\n"),
                         {"nanlist.ply:13:", "face 0", "list length nan"});
  expect_refused_quickly(tmp.write("hugelist.ply", kAscii + kTriangle + "1e300 0 1 2\n"),
                         {"hugelist.ply:13:", "face 0", "not a count"});
  expect_refused_quickly(tmp.write("bigcoord.ply", kAscii + "0 0 0\n1e300 0 0\n0 1 0\n3 0 1 2\n"),
                         {"bigcoord.ply:11:", "vertex 1", "beyond float range"});
  // Binary: a float index that is NaN.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar float vertex_indices\nend_header\n";
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) ply.append(reinterpret_cast<const char*>(&v), 4);
  ply += char(3);
  for (float v : {0.f, 1.f, std::numeric_limits<float>::quiet_NaN()}) ply.append(reinterpret_cast<const char*>(&v), 4);
  expect_refused_quickly(tmp.write("nanindex.ply", ply), {"nanindex.ply", "face 0", "vertex index nan"});
}

TEST(PlyHeader, OffCountsAreCheckedBeforeOpenMesh) {
  TempDir tmp;
  expect_refused_quickly(tmp.write("negative.off", "OFF\n-3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                         {"negative.off:2:", "vertex count '-3'"});
  expect_refused_quickly(tmp.write("negfaces.off", "OFF\n3 -1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                         {"negfaces.off:2:", "face count '-1'"});
  expect_refused_quickly(tmp.write("fraction.off", "OFF\n2.5 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                         {"fraction.off:2:", "not a count"});
  expect_refused_quickly(tmp.write("billions.off", "OFF\n4000000000 4000000000 0\n0 0 0\n"),
                         {"billions.off", "ends early"});
  // Rows long enough for the counts (at least 6 bytes a vertex, 8 a face), one face short.
  expect_refused_quickly(tmp.write("fewer.off", "OFF\n3 1 0\n0.0 0.0 0.0\n1.0 0.0 0.0\n0.0 1.0 0.0\n3 0 1\n"),
                         {"fewer.off:6:", "only 2 indices"});
  expect_refused_quickly(tmp.write("short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
                         {"short.off:2:", "ends early", "at least 25 bytes, the file has 24"});
  expect_refused_quickly(tmp.write("fracindex.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n"),
                         {"fracindex.off:6:", "face index 1.5"});
}

TEST(PlyHeader, ValidHeadersStillLoad) {
  TempDir tmp;
  // Comments, obj_info, CRLF line ends, the sized type names, an extra element.
  std::string ply =
      "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info nothing\r\n"
      "element vertex 3\r\nproperty float32 x\r\nproperty float32 y\r\nproperty float32 z\r\n"
      "property uint8 red\r\n"
      "element face 1\r\nproperty list uint8 int32 vertex_indices\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
      "0 0 0 1\r\n1 0 0 2\r\n0 1 0 3\r\n3 0 1 2\r\n0 1\r\n";
  Mesh m = load_mesh(tmp.write("valid.ply", ply));
  EXPECT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.triangles.size(), 1u);
  // The smallest ASCII body: exactly as many bytes as the bound allows.
  m = load_mesh(tmp.write("tight.ply", kAscii + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2"));
  EXPECT_EQ(m.triangles.size(), 1u);
  m = load_mesh(tmp.write("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_EQ(m.triangles.size(), 1u);
}

}  // namespace
}  // namespace plumbago
