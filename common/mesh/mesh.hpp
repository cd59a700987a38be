// Triangle meshes, loaded through OpenMesh or made procedurally.
#pragma once

#include <glm/glm.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace plumbago {

struct Mesh {
  std::string name;                   // file path or "procedural:<kind>"
  std::vector<glm::vec3> positions;   // welded: no two vertices share a position
  std::vector<glm::vec3> normals;     // unit, area-weighted average of face normals
  std::vector<glm::uvec3> triangles;  // counter-clockwise seen from outside

  glm::vec3 bbox_min() const;
  glm::vec3 bbox_max() const;
  float bbox_diagonal() const;
};

// A mesh refused: the message names the file (and line or element where known).
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads OBJ, OFF, PLY (including binary PLY tristrips) and STL (OBJ and PLY through
// OpenMesh once checked, ASCII OFF and STL by common/mesh/mesh_formats.hpp); polygons are
// triangulated, vertices welded, normals computed. Refuses with MeshError: a missing or
// unreadable file, an unknown format, no faces, NaN/Inf coordinates, face indices out of
// range, a file cut short, counts over the file's size or the memory budget
// (docs/bad-input.md).
Mesh load_mesh(const std::string& path);

// Area-weighted vertex normals; a vertex whose faces all have zero area gets (0,0,1)
// rather than NaN.
void compute_normals(Mesh& mesh);

// Merges vertices with bit-identical positions and drops the faces that become
// degenerate in index (two equal corners); returns how many vertices were merged.
size_t weld_vertices(Mesh& mesh);

// Throws MeshError if any position is NaN/Inf or any index is out of range.
void validate_mesh(const Mesh& mesh);

}  // namespace plumbago
