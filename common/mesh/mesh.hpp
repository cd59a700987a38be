// Triangle meshes, read from files (common/mesh/mesh_io.cpp) or made procedurally.
#pragma once

#include <glm/glm.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace plumbago {

// The coordinate bound of a scene (kMaxCoordinate, common/scene/camera.hpp,
// docs/bad-input.md), which refuses a mesh file beyond it; load_mesh names it when a file
// so far beyond it has no face left (the corners one double apart there).
constexpr double kMaxMeshCoordinate = 1e9;

// What load_mesh removed from a file's faces and vertices (plumbago render --stats).
struct MeshCleanup {
  size_t merged_vertices = 0;   // welded into another vertex
  size_t degenerate_faces = 0;  // two corners the same vertex once welded: dropped
  size_t duplicate_faces = 0;   // the same corners in the same cyclic order as an earlier face: dropped
};

struct Mesh {
  std::string name;                   // file path or "procedural:<kind>"
  std::vector<glm::vec3> positions;   // welded: no two vertices share a position
  std::vector<glm::vec3> normals;     // unit, area-weighted average of face normals
  std::vector<glm::uvec3> triangles;  // counter-clockwise seen from outside; no two the same
  // The surface's parameterization, (u, v) per face corner (3 f + k), where it has one: an OBJ
  // file's `vt` (when every face gives them), a procedural surface's own. Empty where none.
  std::vector<glm::vec2> uvs;
  // Where position 0 lies in the file's coordinates, in double: vertex i lies at
  // origin + positions[i] there. load_mesh centers a file's coordinates on their bounding
  // box in double, so that a file far from 0 keeps its precision in float.
  glm::dvec3 origin{0.0};
  MeshCleanup cleanup;

  glm::vec3 bbox_min() const;
  glm::vec3 bbox_max() const;
  float bbox_diagonal() const;
};

// A mesh refused: the message names the file (and line or element where known).
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads OBJ, OFF, PLY (including binary PLY tristrips) and STL with the project's readers
// (common/mesh/mesh_formats.hpp), coordinates in double; centers them (Mesh::origin),
// welds vertices and drops degenerate and duplicate faces (center_and_weld), computes the
// normals. Refuses with MeshError: a missing or unreadable file, a path too long for the
// system, an unknown format, no faces, NaN/Inf coordinates or ones beyond
// ±kMaxMeshCoordinate, face indices out of range, a file cut short, counts over the
// file's size or the memory budget (docs/bad-input.md).
Mesh load_mesh(const std::string& path);

// Area-weighted vertex normals; a vertex whose faces all have zero area gets (0,0,1)
// rather than NaN.
void compute_normals(Mesh& mesh);

// Merges vertices with bit-identical positions and drops the faces that become
// degenerate in index (two equal corners), with their uvs; returns how many vertices were merged. For
// meshes made in float (procedural); files are welded by center_and_weld
// (common/mesh/mesh_formats.hpp).
size_t weld_vertices(Mesh& mesh);

// Throws MeshError if any position is NaN/Inf or any index is out of range.
void validate_mesh(const Mesh& mesh);

// validate_mesh, and one normal per position, as a mesh both backends draw needs (a mesh
// made in code gets them from compute_normals). Throws MeshError naming the mesh.
void validate_drawable_mesh(const Mesh& mesh);

}  // namespace plumbago
