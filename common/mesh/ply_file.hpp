// PLY files, read by the project's code: OpenMesh's PLY reader does not read triangle
// strips (element "tristrips", -1 ending a strip, as in ../shared/models/igea.ply), reads
// NaN/Inf coordinates and out-of-range indices as zeros or drops them without a word, and
// reads coordinates as float (a file at 1e6 lost most of its vertices).
#pragma once

#include <string>

#include "common/mesh/mesh_formats.hpp"

namespace plumbago {

// Reads every element of an ASCII or binary PLY file: unwelded positions, the faces
// (fan-triangulated) and the strips' triangles (every other one flipped so that all keep
// the strip's winding; triangles with a repeated corner dropped), coordinates in double
// (float and double properties alike). Throws MeshError naming the file, the element
// and, for ASCII, the line.
MeshFile read_ply(const std::string& path);

}  // namespace plumbago
