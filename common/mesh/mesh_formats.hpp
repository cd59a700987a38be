// The mesh formats the project reads with its own code: every one of them, since
// OpenMesh's readers parse coordinates as float (a file at 1e6 or 1e7 lost most of its
// vertices before it could be centered). ASCII OFF (OpenMesh's reader takes no comment
// lines and trusts its counts), STL, ASCII and binary (OpenMesh's reader accepts NaN
// coordinates, a truncated ASCII file and a binary one whose size does not match its
// triangle count), OBJ (checked line by line) and PLY (common/mesh/ply_file.hpp). Each
// returns a MeshFile: the file's coordinates in double, unwelded, and fan-triangulated
// faces; load_mesh (common/mesh/mesh_io.cpp) validates, centers in double, welds and
// computes the normals. Refusals are MeshErrors naming the file and the line (ASCII) or
// the element or facet (binary).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago {

// A mesh file as read: the file's coordinates in double (binary STL and float PLY hold
// float ones, widened exactly), faces as triangles indexing them.
struct MeshFile {
  std::string name;
  std::vector<glm::dvec3> positions;
  std::vector<glm::uvec3> triangles;
  // OBJ's texture coordinates (`vt`), and per triangle the indices of its corners' (empty
  // unless every face gives them).
  std::vector<glm::dvec2> texcoords;
  std::vector<glm::uvec3> texcoord_triangles;
};

// The file's coordinates made a Mesh: centered on their bounding box's center, in double
// (Mesh::origin), then rounded once to float; vertices whose centered coordinates are the
// same float are merged. The weld's tolerance is thus float's spacing at the centered
// coordinate: at most 2^-24 of the object's half-extent, relative to its size and not to
// its place (the same mesh at 0 and at 1e7 welds the same), and it merges only vertices
// that the renderers, which work in float relative to the objects' center, could not hold
// apart. Faces with two corners on one vertex are dropped, and so are faces with the same
// corners in the same cyclic order as an earlier one; a face with the opposite order is
// kept (a two-sided sheet). Counts in Mesh::cleanup. No normals. A kept face keeps its
// corners' texture coordinates (Mesh::uvs).
Mesh center_and_weld(const MeshFile& file);

MeshFile read_off(const std::string& path);
MeshFile read_stl(const std::string& path);
MeshFile read_obj(const std::string& path);

namespace mesh_text {

// A whole word that reads as a number of float range ("1e39" does not: infinite in
// float), kept in double.
bool is_finite_float(const std::string& word, double* value = nullptr);
// The words of a line, up to a '#' comment when `comments` is set.
std::vector<std::string> words(const std::string& line, bool comments);
uint64_t file_size(const std::string& path);
// Refuses with "PATH:LINE: WHAT" (LINE left out when 0) when a mesh of these counts is
// over the memory budget (common/util/memory_budget.hpp).
void check_mesh_budget(const std::string& path, size_t line, double vertices, double triangles);
// Triangles (c0, ck, ck+1) of a polygon, appended to `triangles`.
void add_fan(const std::vector<unsigned>& polygon, std::vector<glm::uvec3>& triangles);

}  // namespace mesh_text

}  // namespace plumbago
