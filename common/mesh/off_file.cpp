// ASCII OFF: "[ST][C][N]OFF" (the keyword may carry the counts), "V F [E]", V vertex rows
// (x y z, then normals, colors or texture coordinates, ignored), F face rows
// (n i1 .. in, then an optional color); '#' starts a comment anywhere.
#include <cmath>
#include <fstream>
#include <regex>

#include "common/mesh/mesh_formats.hpp"

namespace plumbago {

namespace {

using mesh_text::words;

// Shortest rows: "0 0 0\n" and "3 0 0 0\n" (the last one may lack its newline).
constexpr uint64_t kMinVertexRowBytes = 6, kMinFaceRowBytes = 8;

class OffReader {
 public:
  explicit OffReader(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw MeshError(path + ": cannot be read");
  }

  MeshFile read() {
    std::vector<std::string> w = header();
    read_counts(w);
    MeshFile m;
    m.name = path_;
    m.positions.reserve(vertices_);
    for (size_t v = 0; v < vertices_; ++v) m.positions.push_back(vertex_row(next_row("vertex", v)));
    for (size_t f = 0; f < faces_; ++f) mesh_text::add_fan(face_row(next_row("face", f)), m.triangles);
    return m;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw MeshError(path_ + ":" + std::to_string(line_) + ": " + what);
  }

  // The next line with words, or none at the end of the file.
  bool next_line(std::vector<std::string>& w) {
    for (std::string line; std::getline(in_, line);) {
      ++line_;
      bytes_read_ += line.size() + 1;
      w = words(line, true);
      if (!w.empty()) return true;
    }
    return false;
  }

  // The keyword's words after it (counts, when on the same line).
  std::vector<std::string> header() {
    std::vector<std::string> w;
    if (!next_line(w)) throw MeshError(path_ + ": the file is empty");
    if (w[0].find("OFF") == std::string::npos) fail("not an OFF file (no OFF keyword)");
    if (w.size() > 1 && w[1] == "BINARY")
      fail("binary OFF is not read (its counts cannot be checked as text): convert it to ASCII OFF, PLY or STL");
    if (!std::regex_match(w[0], std::regex("(ST)?C?N?OFF")))
      fail("OFF variant '" + w[0] + "' is not read ([ST][C][N]OFF only: no 4D, no nOFF)");
    w.erase(w.begin());
    return w;
  }

  size_t count(const std::string& word, const char* what) const {
    char* end = nullptr;
    double v = std::strtod(word.c_str(), &end);
    if (*end != '\0' || !(v >= 0) || v != std::floor(v) || v > 1e15)
      fail(std::string(what) + " '" + word + "' is not a count");
    return size_t(v);
  }

  // "V F [E]", checked against what the rest of the file can hold and the memory budget.
  void read_counts(std::vector<std::string> w) {
    if (w.empty() && !next_line(w)) fail("the file ends before the counts (V F E)");
    if (w.size() < 2 || w.size() > 3)
      fail("expected the counts 'V F [E]', found " + std::to_string(w.size()) + " words");
    vertices_ = count(w[0], "vertex count");
    faces_ = count(w[1], "face count");
    if (w.size() > 2) count(w[2], "edge count");
    const uint64_t left = mesh_text::file_size(path_) - std::min<uint64_t>(bytes_read_, mesh_text::file_size(path_));
    const double least = double(vertices_) * kMinVertexRowBytes + double(faces_) * kMinFaceRowBytes - 1;
    if (least > double(left))
      fail("the file ends early: " + std::to_string(vertices_) + " vertices and " + std::to_string(faces_) +
           " faces need at least " + std::to_string(uint64_t(least)) + " bytes, the file has " + std::to_string(left) +
           " after the counts");
    mesh_text::check_mesh_budget(path_, line_, double(vertices_), double(faces_));
    counts_line_ = line_;
  }

  std::vector<std::string> next_row(const char* what, size_t index) {
    std::vector<std::string> w;
    if (!next_line(w))
      throw MeshError(path_ + ": the file ends early: line " + std::to_string(counts_line_) + " declares " +
                      std::to_string(vertices_) + " vertices and " + std::to_string(faces_) + " faces, " + what + " " +
                      std::to_string(index) + " is missing");
    for (const auto& word : w)
      if (!mesh_text::is_finite_float(word)) fail("'" + word + "' is not a finite number");
    return w;
  }

  glm::dvec3 vertex_row(const std::vector<std::string>& w) const {
    if (w.size() < 3) fail("a vertex needs 3 coordinates, found " + std::to_string(w.size()));
    glm::dvec3 p;
    for (int c = 0; c < 3; ++c) mesh_text::is_finite_float(w[c], &p[c]);
    return p;
  }

  std::vector<unsigned> face_row(const std::vector<std::string>& w) const {
    size_t n = count(w[0], "face corner count");
    if (n < 3) fail("a face needs at least 3 corners, found " + w[0]);
    if (n + 1 > w.size()) fail("face with " + w[0] + " corners has only " + std::to_string(w.size() - 1) + " indices");
    std::vector<unsigned> corners;
    for (size_t k = 1; k <= n; ++k) {
      double i = std::strtod(w[k].c_str(), nullptr);
      if (i < 0 || i >= double(vertices_) || i != std::floor(i))
        fail("face index " + w[k] + " is out of range (" + std::to_string(vertices_) + " vertices, counted from 0)");
      corners.push_back(unsigned(i));
    }
    return corners;
  }

  std::string path_;
  std::ifstream in_;
  size_t line_ = 0, counts_line_ = 0, vertices_ = 0, faces_ = 0;
  uint64_t bytes_read_ = 0;
};

}  // namespace

MeshFile read_off(const std::string& path) { return OffReader(path).read(); }

}  // namespace plumbago
