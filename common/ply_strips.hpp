// Binary PLY files whose faces are stored as triangle strips (element "tristrips" with a
// list "vertex_indices", -1 ending a strip), which OpenMesh's PLY reader does not read.
#pragma once

#include <string>

#include "common/mesh.hpp"

namespace plumbago {

bool ply_has_triangle_strips(const std::string& path);
// Unwelded positions and the strips' triangles (every other one flipped so that all keep
// the strip's winding; triangles with a repeated corner are dropped). Throws MeshError.
Mesh read_ply_triangle_strips(const std::string& path);

}  // namespace plumbago
