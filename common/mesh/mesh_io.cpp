// Mesh files, read by the project's own readers (common/mesh/mesh_formats.hpp) in double,
// then centered and welded (center_and_weld) before they become float.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "common/mesh/mesh.hpp"
#include "common/mesh/mesh_formats.hpp"
#include "common/mesh/ply_file.hpp"
#include "common/util/input_file.hpp"

namespace plumbago {

namespace {

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

// The texture coordinate index of an OBJ face corner ("i/t", "i/t/n"), as corner_index reads
// the vertex's; none where the corner gives none ("i", "i//n") or it is not a whole number.
std::optional<long> corner_texcoord(const std::string& corner) {
  size_t slash = corner.find('/');
  if (slash == std::string::npos) return std::nullopt;
  std::string rest = corner.substr(slash + 1);
  return corner_index(rest.substr(0, rest.find('/')));
}

// An OBJ index (1-based, negative counting back from the `before` read so far) as a 0-based
// one among `count`; none when out of range.
std::optional<size_t> obj_index(long index, size_t count, size_t before) {
  if (index == 0 || (index > 0 && size_t(index) > count) || (index < 0 && uint64_t(-(index + 1)) >= before))
    return std::nullopt;
  return index > 0 ? size_t(index - 1) : size_t(long(before) + index);
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

// OBJ text checked before read_obj reads it, so that a bad coordinate or index is
// reported with its line (OpenMesh, which read it before, skipped such faces with a
// warning), a file cut off inside a data line is refused, and the counts are held to the
// memory budget before anything is stored. Two
// passes, nothing stored: the first counts the vertices (a positive index may name one
// defined after its face), the second checks the indices.
void check_obj_lines(const std::string& path) {
  auto fail = [&](size_t at, const std::string& what) {
    throw MeshError(path + ":" + std::to_string(at) + ": " + what);
  };
  size_t vertices = 0, triangles = 0;
  for_each_obj_line(path, [&](size_t number, const std::vector<std::string>& w) {
    if (w[0] == "v" || w[0] == "vt") {
      const bool vertex = w[0] == "v";
      vertices += vertex;
      for (size_t k = 1; k <= (vertex ? 3u : 2u); ++k)
        if (k >= w.size() || !mesh_text::is_finite_float(w[k]))
          fail(number, std::string(vertex ? "vertex" : "texture") + " coordinate '" +
                           (k < w.size() ? w[k] : std::string()) + "' is not a finite number");
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
      if (!obj_index(index, vertices, before))
        fail(number, "face index " + w[k].substr(0, w[k].find('/')) + " is out of range (" +
                         std::to_string(index > 0 ? vertices : before) + " vertices" +
                         (index > 0 ? " in the file)" : " before it)"));
    }
  });
}

}  // namespace

// OBJ: `v x y z` (in double), `vt u v` and `f` lines (corners `i`, `i/t`, `i//n`, `i/t/n`;
// negative indices count back), once check_obj_lines has checked every line; polygons
// fan-triangulated. The texture coordinates are kept when every corner of every face names
// one the file has (else the mesh has none: they are optional, the geometry stands).
MeshFile read_obj(const std::string& path) {
  check_obj_lines(path);
  MeshFile m;
  m.name = path;
  for_each_obj_line(path, [&](size_t, const std::vector<std::string>& w) {
    if (w[0] == "v") {
      glm::dvec3 p;
      for (int c = 0; c < 3; ++c) mesh_text::is_finite_float(w[size_t(c) + 1], &p[c]);
      m.positions.push_back(p);
    } else if (w[0] == "vt") {
      glm::dvec2 t;
      for (int c = 0; c < 2; ++c) mesh_text::is_finite_float(w[size_t(c) + 1], &t[c]);
      m.texcoords.push_back(t);
    }
  });
  size_t before = 0, texcoords_before = 0;
  bool every_corner = true;
  std::vector<unsigned> polygon, texcoord_polygon;
  for_each_obj_line(path, [&](size_t, const std::vector<std::string>& w) {
    before += w[0] == "v", texcoords_before += w[0] == "vt";
    if (w[0] != "f") return;
    polygon.clear(), texcoord_polygon.clear();
    for (size_t k = 1; k < w.size(); ++k) {
      polygon.push_back(unsigned(*obj_index(*corner_index(w[k]), m.positions.size(), before)));
      const std::optional<long> t = corner_texcoord(w[k]);
      const std::optional<size_t> at = t ? obj_index(*t, m.texcoords.size(), texcoords_before) : std::nullopt;
      every_corner = every_corner && at;
      if (at) texcoord_polygon.push_back(unsigned(*at));
    }
    mesh_text::add_fan(polygon, m.triangles);
    if (every_corner) mesh_text::add_fan(texcoord_polygon, m.texcoord_triangles);
  });
  if (!every_corner) m.texcoord_triangles.clear();
  return m;
}

namespace {

MeshFile read_by_format(const std::string& path, const std::string& ext) {
  if (ext == ".off") return read_off(path);
  if (ext == ".stl") return read_stl(path);
  if (ext == ".obj") return read_obj(path);
  return read_ply(path);
}

// NaN or infinite coordinates, indices out of range, no faces: of a Mesh, or of a
// MeshFile's coordinates in double before they are centered.
template <class Arrays>
void validate_arrays(const Arrays& m) {
  for (size_t i = 0; i < m.positions.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(m.positions[i][c]))
        throw MeshError(m.name + ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  for (size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (m.triangles[t][k] >= m.positions.size())
        throw MeshError(m.name + ": face " + std::to_string(t) + " has a vertex index out of range");
  if (m.triangles.empty()) throw MeshError(m.name + ": the mesh has no faces");
}

}  // namespace

void validate_mesh(const Mesh& mesh) { validate_arrays(mesh); }

void validate_drawable_mesh(const Mesh& mesh) {
  validate_mesh(mesh);
  if (mesh.normals.size() != mesh.positions.size())
    throw MeshError(mesh.name + ": " + std::to_string(mesh.normals.size()) + " normals for " +
                    std::to_string(mesh.positions.size()) + " vertices (compute_normals makes them)");
}

namespace {

std::string coordinate_text(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

struct PositionHash {
  size_t operator()(const glm::vec3& p) const {
    size_t h = 0;
    for (int c = 0; c < 3; ++c) h = h * 1000003u ^ std::hash<float>()(p[c]);
    return h;
  }
};

// A face up to the rotation of its corners: the smallest index first, the cyclic order
// (and so the orientation) kept.
glm::uvec3 canonical_face(glm::uvec3 t) {
  if (t[1] < t[0] && t[1] < t[2]) return {t[1], t[2], t[0]};
  if (t[2] < t[0] && t[2] < t[1]) return {t[2], t[0], t[1]};
  return t;
}

struct FaceHash {
  size_t operator()(const glm::uvec3& t) const {
    return (size_t(t[0]) * 0x9E3779B97F4A7C15ull) ^ (size_t(t[1]) * 0xC2B2AE3D27D4EB4Full) ^ size_t(t[2]);
  }
};

// Why no face is left after welding: the faces are degenerate, or the coordinates lie so
// far beyond the bound that even double does not hold the mesh apart there (a unit mesh
// at 1e17). A mesh within reach of double but beyond the bound is refused by the scene
// (common/scene/scene.cpp, check_extent), which names the bound too.
std::string no_face_left(const MeshFile& f) {
  size_t farthest = 0;
  double largest = 0;
  for (size_t i = 0; i < f.positions.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (std::abs(f.positions[i][c]) > largest) largest = std::abs(f.positions[i][c]), farthest = i;
  if (largest <= kMaxMeshCoordinate) return "every face is degenerate (no faces left after welding)";
  const glm::dvec3& p = f.positions[farthest];
  return "vertex " + std::to_string(farthest) + " lies at (" + coordinate_text(p.x) + ", " + coordinate_text(p.y) +
         ", " + coordinate_text(p.z) + "), beyond ±" + coordinate_text(kMaxMeshCoordinate) +
         " (the largest coordinate float buffers can hold): no face is left apart there";
}

}  // namespace

Mesh center_and_weld(const MeshFile& file) {
  Mesh m;
  m.name = file.name;
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec3& p : file.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  m.origin = file.positions.empty() ? glm::dvec3(0.0) : (lo + hi) * 0.5;
  std::unordered_map<glm::vec3, unsigned, PositionHash> first;
  std::vector<unsigned> remap(file.positions.size());
  for (size_t i = 0; i < file.positions.size(); ++i) {
    const glm::vec3 p(file.positions[i] - m.origin);  // rounded once, from double
    auto [it, added] = first.emplace(p, unsigned(m.positions.size()));
    if (added) m.positions.push_back(p);
    remap[i] = it->second;
  }
  m.cleanup.merged_vertices = file.positions.size() - m.positions.size();
  std::unordered_set<glm::uvec3, FaceHash> seen;
  m.triangles.reserve(file.triangles.size());
  const bool uvs = !file.texcoord_triangles.empty();
  for (size_t f = 0; f < file.triangles.size(); ++f) {
    const glm::uvec3& t = file.triangles[f];
    glm::uvec3 r(remap[t[0]], remap[t[1]], remap[t[2]]);
    if (r[0] == r[1] || r[1] == r[2] || r[0] == r[2]) {
      ++m.cleanup.degenerate_faces;
    } else if (!seen.insert(canonical_face(r)).second) {
      ++m.cleanup.duplicate_faces;
    } else {
      m.triangles.push_back(r);
      for (int k = 0; k < 3 && uvs; ++k) m.uvs.emplace_back(file.texcoords[file.texcoord_triangles[f][k]]);
    }
  }
  return m;
}

Mesh load_mesh(const std::string& path) {
  std::error_code error;
  if (std::string why = path_length_fault(path); !why.empty())
    throw MeshError(shortened_path(path) + ": cannot read the mesh file: " + why);
  if (!std::filesystem::is_regular_file(path, error)) throw MeshError(path + ": no such mesh file");
  std::string ext = lowercase_extension(path);
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw MeshError(path + ": unknown mesh format '" + ext + "' (OBJ, OFF, PLY or STL)");
  MeshFile file = read_by_format(path, ext);
  validate_arrays(file);
  Mesh m = center_and_weld(file);
  if (m.triangles.empty()) throw MeshError(path + ": " + no_face_left(file));
  compute_normals(m);
  return m;
}

}  // namespace plumbago
