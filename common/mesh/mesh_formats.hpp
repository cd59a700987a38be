// The mesh formats the project reads with its own code: ASCII OFF (OpenMesh's reader
// takes no comment lines and trusts its counts) and STL, ASCII and binary (OpenMesh's
// reader accepts NaN coordinates, a truncated ASCII file and a binary one whose size
// does not match its triangle count). Each returns unwelded positions and fan-triangulated
// faces; load_mesh (common/mesh/mesh_io.cpp) validates, welds and computes the normals.
// Refusals are MeshErrors naming the file and the line (ASCII) or the facet (binary STL).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago {

Mesh read_off(const std::string& path);
Mesh read_stl(const std::string& path);

namespace mesh_text {

// A whole word that reads as a float of float range ("1e39" does not: infinite).
bool is_finite_float(const std::string& word, float* value = nullptr);
// The words of a line, up to a '#' comment when `comments` is set.
std::vector<std::string> words(const std::string& line, bool comments);
uint64_t file_size(const std::string& path);
// Refuses with "PATH:LINE: WHAT" (LINE left out when 0) when a mesh of these counts is
// over the memory budget (common/util/memory_budget.hpp).
void check_mesh_budget(const std::string& path, size_t line, double vertices, double triangles);
// Triangles (c0, ck, ck+1) of a polygon, appended to `mesh`.
void add_fan(const std::vector<unsigned>& polygon, Mesh& mesh);

}  // namespace mesh_text

}  // namespace plumbago
