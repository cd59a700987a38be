// Mesh files through OpenMesh (OBJ, OFF, PLY, STL), plus the binary-PLY triangle strips
// OpenMesh cannot read (../shared/models/igea.ply).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "common/mesh.hpp"
#include "common/ply_strips.hpp"

namespace plumbago {

namespace {

using OpenMeshTri = OpenMesh::TriMesh_ArrayKernelT<>;

std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// OBJ text checked line by line before OpenMesh reads it, so that a bad coordinate or
// index is reported with its line (OpenMesh skips such faces with a warning).
void check_obj_lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  size_t vertices = 0, number = 0;
  std::vector<std::pair<size_t, long>> face_indices;  // (line, index)
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
        float v = std::strtof(word.c_str(), nullptr);
        if (word.empty() || !std::isfinite(v))
          throw MeshError(path + ":" + std::to_string(number) + ": vertex coordinate '" + word +
                          "' is not a finite number");
      }
    } else if (tag == "f") {
      for (std::string corner; ss >> corner;) face_indices.push_back({number, std::atol(corner.c_str())});
    }
  }
  for (auto [at, index] : face_indices) {  // negative indices count back from the end
    if (index == 0 || std::labs(index) > long(vertices))
      throw MeshError(path + ":" + std::to_string(at) + ": face index " + std::to_string(index) +
                      " is out of range (the file has " + std::to_string(vertices) + " vertices)");
  }
}

// Reads through OpenMesh with its complaints captured instead of printed.
OpenMeshTri read_with_openmesh(const std::string& path) {
  OpenMeshTri om;
  std::ostringstream complaints;
  ::omerr().disconnect(std::cerr);
  ::omerr().connect(complaints);
  ::omlog().disable();
  OpenMesh::IO::Options options;
  bool ok = OpenMesh::IO::read_mesh(om, path, options);
  ::omerr().disconnect(complaints);
  ::omerr().connect(std::cerr);
  ::omlog().enable();
  std::string text = complaints.str();
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
  Mesh m = ext == ".ply" && ply_has_triangle_strips(path) ? read_ply_triangle_strips(path)
                                                          : flat_arrays(read_with_openmesh(path), path);
  validate_mesh(m);
  weld_vertices(m);
  if (m.triangles.empty()) throw MeshError(path + ": every face is degenerate (no faces left after welding)");
  compute_normals(m);
  return m;
}

}  // namespace plumbago
