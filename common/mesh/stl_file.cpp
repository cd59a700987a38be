// STL: binary when the size is 84 + 50 n for the count n at byte 80 (some binary files
// begin with "solid" too), else ASCII when it begins with "solid", else refused.
// ASCII: solid [name] { facet normal nx ny nz  outer loop  vertex x y z (3 times)
// endloop  endfacet } endsolid [name]; a file without 'endsolid' is truncated.
#include <cmath>
#include <cstring>
#include <fstream>

#include "common/mesh/mesh_formats.hpp"

namespace plumbago {

namespace {

constexpr uint64_t kBinaryHeader = 84, kBinaryFacet = 50;

uint32_t binary_count(const std::string& bytes) {
  uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);  // little-endian, as the format says (and as we run)
  return n;
}

// Binary STL holds float32 coordinates by its format: a binary file far from the origin
// has lost its precision before it is read (float at 1e6 resolves 0.06). They are
// widened to double exactly.
MeshFile read_binary(const std::string& path, std::ifstream& in, uint32_t n) {
  mesh_text::check_mesh_budget(path, 0, 3.0 * n, n);
  MeshFile m;
  m.name = path;
  m.positions.reserve(size_t(3) * n);
  in.seekg(std::streamoff(kBinaryHeader));
  char facet[kBinaryFacet];
  for (uint32_t t = 0; t < n; ++t) {
    if (!in.read(facet, kBinaryFacet)) throw MeshError(path + ": cannot be read (facet " + std::to_string(t) + ")");
    for (int k = 0; k < 3; ++k) {
      glm::vec3 p;
      std::memcpy(&p, facet + 12 * (k + 1), 12);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw MeshError(path + ": facet " + std::to_string(t) + " has a NaN or infinite coordinate");
      m.positions.push_back(glm::dvec3(p));
    }
    unsigned first = unsigned(3 * t);
    m.triangles.push_back({first, first + 1, first + 2});
  }
  return m;
}

class AsciiStlReader {
 public:
  AsciiStlReader(const std::string& path, std::ifstream& in) : path_(path), in_(in) {}

  MeshFile read() {
    MeshFile m;
    m.name = path_;
    in_.seekg(0);
    expect("solid", 1);
    for (auto w = next("facet' or 'endsolid"); w[0] != "endsolid"; w = next("facet' or 'endsolid")) {
      if (w[0] != "facet" || w.size() != 5 || w[1] != "normal") fail("expected 'facet normal nx ny nz' or 'endsolid'");
      for (int c = 2; c < 5; ++c)  // the normal is not used (a NaN one is no harm)
        if (!is_number(w[c])) fail("'" + w[c] + "' is not a number");
      expect("outer", 2);
      for (int k = 0; k < 3; ++k) m.positions.push_back(vertex());
      expect("endloop", 1);
      expect("endfacet", 1);
      unsigned first = unsigned(m.positions.size() - 3);
      m.triangles.push_back({first, first + 1, first + 2});
    }
    mesh_text::check_mesh_budget(path_, line_, double(m.positions.size()), double(m.triangles.size()));
    return m;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw MeshError(path_ + ":" + std::to_string(line_) + ": " + what);
  }

  static bool is_number(const std::string& word) {
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    return !word.empty() && *end == '\0';
  }

  std::vector<std::string> next(const std::string& expected) {
    for (std::string line; std::getline(in_, line);) {
      ++line_;
      if (auto w = mesh_text::words(line, false); !w.empty()) return w;
    }
    throw MeshError(path_ + ":" + std::to_string(line_) + ": the file ends early, where '" + expected +
                    "' should follow (truncated?)");
  }

  // A line that begins with `keyword` and has at least `least` words.
  void expect(const std::string& keyword, size_t least) {
    auto w = next(keyword);
    if (w[0] != keyword || w.size() < least) fail("expected '" + keyword + "', found '" + w[0] + "'");
  }

  // Read in double: ASCII STL can hold coordinates far from the origin exactly.
  glm::dvec3 vertex() {
    auto w = next("vertex");
    if (w[0] != "vertex" || w.size() != 4) fail("expected 'vertex x y z'");
    glm::dvec3 p;
    for (int c = 0; c < 3; ++c)
      if (!mesh_text::is_finite_float(w[c + 1], &p[c]))
        fail("vertex coordinate '" + w[c + 1] + "' is not a finite number");
    return p;
  }

  std::string path_;
  std::ifstream& in_;
  size_t line_ = 0;
};

}  // namespace

MeshFile read_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const uint64_t size = mesh_text::file_size(path);
  std::string head(size_t(std::min<uint64_t>(size, kBinaryHeader)), '\0');
  if (!in || !in.read(head.data(), std::streamsize(head.size()))) throw MeshError(path + ": cannot be read");
  const std::vector<std::string> first = mesh_text::words(head.substr(0, head.find('\n')), false);
  const bool ascii = !first.empty() && first[0] == "solid";
  if (size >= kBinaryHeader) {
    uint32_t n = binary_count(head);
    if (size == kBinaryHeader + kBinaryFacet * uint64_t(n)) return read_binary(path, in, n);
    if (!ascii)
      throw MeshError(path + ": a binary STL of " + std::to_string(n) + " triangles takes 84 + 50 x " +
                      std::to_string(n) + " = " + std::to_string(kBinaryHeader + kBinaryFacet * uint64_t(n)) +
                      " bytes, the file has " + std::to_string(size) + " (truncated, or not an STL file)");
  }
  if (!ascii)
    throw MeshError(path + ": not an STL file (no 'solid' line, and " + std::to_string(size) +
                    " bytes are too few for a binary STL's 84-byte header)");
  return AsciiStlReader(path, in).read();
}

}  // namespace plumbago
