// PLY files read far enough for what OpenMesh's PLY reader does not do: triangle strips
// (element "tristrips", -1 ending a strip, as in ../shared/models/igea.ply), and the
// refusal of NaN/Inf coordinates and out-of-range indices, which it would read as zeros
// or drop without a word.
#pragma once

#include <string>

#include "common/mesh/mesh.hpp"

namespace plumbago {

// Reads every element of an ASCII or binary PLY file: unwelded positions, the faces
// (fan-triangulated) and the strips' triangles (every other one flipped so that all keep
// the strip's winding; triangles with a repeated corner dropped). `has_strips` says
// whether the file has a "tristrips" element. Throws MeshError naming the file, the
// element and, for ASCII, the line.
Mesh read_ply(const std::string& path, bool& has_strips);

}  // namespace plumbago
