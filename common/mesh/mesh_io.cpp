// Mesh files: OBJ and PLY through OpenMesh, each checked first by the project's code so
// that a refusal names the line (and PLY triangle strips, which OpenMesh cannot read,
// ../shared/models/igea.ply, read by it); ASCII OFF and STL by the project's own readers
// (common/mesh/mesh_formats.hpp).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "common/mesh/mesh.hpp"
#include "common/mesh/mesh_formats.hpp"
#include "common/mesh/ply_file.hpp"

namespace plumbago {

namespace {

using OpenMeshTri = OpenMesh::TriMesh_ArrayKernelT<>;

std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The vertex index of an OBJ face corner ("i", "i/t", "i//n", "i/t/n"): a whole number,
// negative counting back; none when the word does not begin with one. Beyond 18 digits,
// the largest long of its sign: out of range in any file.
std::optional<long> corner_index(const std::string& corner) {
  std::string index = corner.substr(0, corner.find('/'));
  const bool negative = !index.empty() && index[0] == '-';
  const size_t digits = index.size() - negative;
  if (digits == 0 || index.find_first_not_of("0123456789", negative) != std::string::npos) return std::nullopt;
  if (digits > 18) return negative ? std::numeric_limits<long>::min() : std::numeric_limits<long>::max();
  return std::stol(index);
}

// An OBJ statement that carries data: the file must not end inside one. A line cut
// mid-way still parses (`f 1 2 3` from `f 1 2 34`), so its missing newline is the signal.
bool is_data_line(const std::vector<std::string>& w) {
  return !w.empty() && (w[0] == "v" || w[0] == "vt" || w[0] == "vn" || w[0] == "f" || w[0] == "l" || w[0] == "p");
}

// Calls visit(line number, words) for each line of an OBJ file that has words; refuses
// a last data line without its newline.
template <class Visit>
void for_each_obj_line(const std::string& path, Visit visit) {
  std::ifstream in(path, std::ios::binary);
  size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::vector<std::string> w = mesh_text::words(line, true);
    if (in.eof() && is_data_line(w))
      throw MeshError(path + ":" + std::to_string(number) +
                      ": the file ends inside this line, without its newline: cut off? (a file ends with a "
                      "newline after its last vertex or face)");
    if (!w.empty()) visit(number, w);
  }
}

// OBJ text checked before OpenMesh reads it, so that a bad coordinate or index is
// reported with its line (OpenMesh skips such faces with a warning), a file cut off
// inside a data line is refused, and the counts are held to the memory budget. Two
// passes, nothing stored: the first counts the vertices (a positive index may name one
// defined after its face), the second checks the indices.
void check_obj_lines(const std::string& path) {
  auto fail = [&](size_t at, const std::string& what) {
    throw MeshError(path + ":" + std::to_string(at) + ": " + what);
  };
  size_t vertices = 0, triangles = 0;
  for_each_obj_line(path, [&](size_t number, const std::vector<std::string>& w) {
    if (w[0] == "v") {
      ++vertices;
      for (size_t k = 1; k <= 3; ++k)
        if (k >= w.size() || !mesh_text::is_finite_float(w[k]))
          fail(number, "vertex coordinate '" + (k < w.size() ? w[k] : std::string()) + "' is not a finite number");
    } else if (w[0] == "f") {
      if (w.size() < 4) fail(number, "a face needs at least 3 corners, found " + std::to_string(w.size() - 1));
      triangles += w.size() - 3;
      for (size_t k = 1; k < w.size(); ++k)
        if (!corner_index(w[k]))
          fail(number, "face corner '" + w[k] + "' does not begin with a vertex index (a whole number)");
    }
  });
  mesh_text::check_mesh_budget(path, 0, double(vertices), double(triangles));
  // Positive indices count from the file's first vertex, negative ones back from the
  // last vertex read before the face.
  size_t before = 0;
  for_each_obj_line(path, [&](size_t number, const std::vector<std::string>& w) {
    before += w[0] == "v";
    if (w[0] != "f") return;
    for (size_t k = 1; k < w.size(); ++k) {
      const long index = *corner_index(w[k]);
      if (index == 0 || (index > 0 && size_t(index) > vertices) || (index < 0 && uint64_t(-(index + 1)) >= before))
        fail(number, "face index " + w[k].substr(0, w[k].find('/')) + " is out of range (" +
                         std::to_string(index > 0 ? vertices : before) + " vertices" +
                         (index > 0 ? " in the file)" : " before it)"));
    }
  });
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
  if (!ok)
    throw MeshError(path + ": OpenMesh cannot read it (unknown format or malformed)" +
                    (text.empty() ? "" : ": " + text));
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

// OBJ through OpenMesh once every line is checked; PLY through OpenMesh once the
// project's reader has read every value (it reads triangle strips itself); OFF and STL
// with the project's own readers.
Mesh read_by_format(const std::string& path, const std::string& ext) {
  if (ext == ".off") return read_off(path);
  if (ext == ".stl") return read_stl(path);
  if (ext == ".obj") check_obj_lines(path);
  bool has_strips = false;
  Mesh strips = ext == ".ply" ? read_ply(path, has_strips) : Mesh{};
  return has_strips ? std::move(strips) : flat_arrays(read_with_openmesh(path), path);
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
  Mesh m = read_by_format(path, ext);
  validate_mesh(m);
  weld_vertices(m);
  if (m.triangles.empty()) throw MeshError(path + ": every face is degenerate (no faces left after welding)");
  compute_normals(m);
  return m;
}

}  // namespace plumbago
