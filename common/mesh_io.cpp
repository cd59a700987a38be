// Mesh files through OpenMesh (OBJ, OFF, PLY, STL), with the text formats checked first so
// that a refusal names the line, and the PLY triangle strips OpenMesh cannot read
// (../shared/models/igea.ply).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "common/mesh.hpp"
#include "common/ply_file.hpp"

namespace plumbago {

namespace {

using OpenMeshTri = OpenMesh::TriMesh_ArrayKernelT<>;

std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// A whole word that reads as a finite float (1e39 does not: it would be infinite). The
// whole word, not up to a NUL byte within it: "\0\0032" is not a number.
bool is_finite_number(const std::string& word) {
  char* end = nullptr;
  float v = std::strtof(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size() && std::isfinite(v);
}

// OBJ text checked line by line before OpenMesh reads it, so that a bad coordinate or
// index is reported with its line (OpenMesh skips such faces with a warning).
void check_obj_lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  size_t vertices = 0, number = 0;
  struct FaceIndex {
    size_t line;
    long index;
    size_t vertices_before;
  };
  std::vector<FaceIndex> face_indices;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream ss(line);
    std::string tag;
    ss >> tag;
    if (tag == "v") {
      ++vertices;
      for (int k = 0; k < 3; ++k) {
        std::string word;
        ss >> word;
        if (!is_finite_number(word))
          throw MeshError(path + ":" + std::to_string(number) + ": vertex coordinate '" + word +
                          "' is not a finite number");
      }
    } else if (tag == "f") {
      for (std::string corner; ss >> corner;) face_indices.push_back({number, std::atol(corner.c_str()), vertices});
    }
  }
  // Positive indices count from the file's first vertex, negative ones back from the
  // last vertex read before the face.
  for (const FaceIndex& f : face_indices) {
    if (f.index == 0 || (f.index > 0 && size_t(f.index) > vertices) || (f.index < 0 && size_t(-f.index) > f.vertices_before))
      throw MeshError(path + ":" + std::to_string(f.line) + ": face index " + std::to_string(f.index) +
                      " is out of range (" + std::to_string(f.index > 0 ? vertices : f.vertices_before) +
                      " vertices" + (f.index > 0 ? " in the file)" : " before it)"));
  }
}

// OFF text checked line by line: after the keyword (OFF, COFF, NOFF, ...) every value
// must be a finite number, and each face's indices must name one of the V vertices.
// OpenMesh would read "nan" as garbage and misread everything after it.
void check_off_lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  size_t number = 0, vertices = 0, faces = 0, rows = 0;
  bool counts_read = false;
  // A count must be a whole number from 0 up: a negative one would otherwise become a
  // huge size in OpenMesh's reader (it reserves room for V vertices and F faces).
  auto count = [&](const std::string& word, const char* what) {
    double v = std::strtod(word.c_str(), nullptr);  // std::stod throws on 1e-400
    if (v < 0 || v != std::floor(v))
      throw MeshError(path + ":" + std::to_string(number) + ": " + what + " '" + word + "' is not a count");
    return size_t(std::min(v, 1e15));
  };
  while (std::getline(in, line)) {
    ++number;
    std::istringstream ss(line.substr(0, line.find('#')));
    std::vector<std::string> words;
    for (std::string w; ss >> w;) words.push_back(w);
    if (number == 1 && !words.empty() && words[0].find("OFF") != std::string::npos) {
      // OpenMesh's binary reader trusts the counts (a count of 4 billion in a small file
      // read past its end for minutes); any BINARY on the line, not only where OpenMesh
      // looks for it, or the body would go to its ASCII reader unchecked.
      if (line.find("BINARY") != std::string::npos)
        throw MeshError(path + ":1: binary OFF is not read (its counts cannot be checked): convert it to ASCII "
                        "OFF, PLY or STL");
      words.erase(words.begin());
    }
    if (words.empty()) continue;
    for (const auto& w : words)
      if (!is_finite_number(w))
        throw MeshError(path + ":" + std::to_string(number) + ": '" + w + "' is not a finite number");
    if (!counts_read) {  // "V F E"
      vertices = count(words[0], "vertex count");
      faces = words.size() > 1 ? count(words[1], "face count") : 0;
      if (words.size() > 2) count(words[2], "edge count");
      counts_read = true;
    } else if (size_t row = rows++; row >= vertices && row < vertices + faces) {  // "n i1 ... in [color]"
      size_t n = count(words[0], "face corner count");
      if (n + 1 > words.size())
        throw MeshError(path + ":" + std::to_string(number) + ": face with " + words[0] + " corners has only " +
                        std::to_string(words.size() - 1) + " indices");
      for (size_t k = 1; k <= n; ++k)
        if (double i = std::strtod(words[k].c_str(), nullptr); i < 0 || i >= double(vertices) || i != std::floor(i))
          throw MeshError(path + ":" + std::to_string(number) + ": face index " + words[k] +
                          " is out of range (" + std::to_string(vertices) + " vertices, counted from 0)");
    }
  }
  if (!counts_read)  // OpenMesh would use its counts uninitialized
    throw MeshError(path + ": no vertex and face counts after the OFF keyword");
  if (rows < vertices + faces)  // before OpenMesh reserves room for what the counts say
    throw MeshError(path + ": the file ends early (" + std::to_string(vertices) + " vertices and " +
                    std::to_string(faces) + " faces declared, " + std::to_string(rows) + " lines of them found)");
}

// OpenMesh's error stream captured and its log silenced while alive (OpenMesh would
// print a warning per complex edge of a non-manifold mesh).
class CapturedOpenMeshComplaints {
 public:
  CapturedOpenMeshComplaints() {
    ::omerr().disconnect(std::cerr);
    ::omerr().connect(text_);
    ::omlog().disable();
  }
  ~CapturedOpenMeshComplaints() {
    ::omerr().disconnect(text_);
    ::omerr().connect(std::cerr);
    ::omlog().enable();
  }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
};

// Reads through OpenMesh; what it complains about goes into the refusal, not to stderr.
OpenMeshTri read_with_openmesh(const std::string& path) {
  OpenMeshTri om;
  std::string text;
  bool ok;
  {
    CapturedOpenMeshComplaints complaints;
    OpenMesh::IO::Options options;
    ok = OpenMesh::IO::read_mesh(om, path, options);
    text = complaints.text();
  }
  if (!ok) throw MeshError(path + ": OpenMesh cannot read it (unknown format or malformed)" + (text.empty() ? "" : ": " + text));
  if (text.find("invalid vertex index") != std::string::npos)
    throw MeshError(path + ": a face has a vertex index out of range");
  return om;
}

Mesh flat_arrays(const OpenMeshTri& om, const std::string& path) {
  Mesh m;
  m.name = path;
  m.positions.reserve(om.n_vertices());
  for (auto v : om.vertices()) {
    auto p = om.point(v);
    m.positions.push_back({p[0], p[1], p[2]});
  }
  m.triangles.reserve(om.n_faces());
  for (auto f : om.faces()) {
    glm::uvec3 t;
    int k = 0;
    for (auto v : om.fv_range(f)) t[k++] = unsigned(v.idx());
    m.triangles.push_back(t);
  }
  return m;
}

}  // namespace

void validate_mesh(const Mesh& mesh) {
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(mesh.positions[i][c]))
        throw MeshError(mesh.name + ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles[t][k] >= mesh.positions.size())
        throw MeshError(mesh.name + ": face " + std::to_string(t) + " has a vertex index out of range");
  if (mesh.triangles.empty()) throw MeshError(mesh.name + ": the mesh has no faces");
}

size_t weld_vertices(Mesh& mesh) {
  struct Key {
    size_t operator()(const glm::vec3& p) const {
      size_t h = 0;
      for (int c = 0; c < 3; ++c) h = h * 1000003u ^ std::hash<float>()(p[c]);
      return h;
    }
  };
  std::unordered_map<glm::vec3, unsigned, Key> first;
  std::vector<unsigned> remap(mesh.positions.size());
  std::vector<glm::vec3> kept;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    auto [it, added] = first.emplace(mesh.positions[i], unsigned(kept.size()));
    if (added) kept.push_back(mesh.positions[i]);
    remap[i] = it->second;
  }
  std::vector<glm::uvec3> faces;
  for (const auto& t : mesh.triangles) {
    glm::uvec3 r(remap[t[0]], remap[t[1]], remap[t[2]]);
    if (r[0] != r[1] && r[1] != r[2] && r[0] != r[2]) faces.push_back(r);
  }
  size_t merged = mesh.positions.size() - kept.size();
  mesh.positions = std::move(kept);
  mesh.triangles = std::move(faces);
  return merged;
}

Mesh load_mesh(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw MeshError(path + ": no such mesh file");
  std::string ext = lowercase_extension(path);
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw MeshError(path + ": unknown mesh format '" + ext + "' (OBJ, OFF, PLY or STL)");
  if (ext == ".obj") check_obj_lines(path);
  if (ext == ".off") check_off_lines(path);
  bool has_strips = false;
  Mesh strips = ext == ".ply" ? read_ply(path, has_strips) : Mesh{};  // checks every value
  Mesh m = has_strips ? std::move(strips) : flat_arrays(read_with_openmesh(path), path);
  validate_mesh(m);
  weld_vertices(m);
  if (m.triangles.empty()) throw MeshError(path + ": every face is degenerate (no faces left after welding)");
  compute_normals(m);
  return m;
}

}  // namespace plumbago
