// A mesh written as a text file of each format the project reads (OBJ, OFF, ASCII PLY,
// ASCII STL), its coordinates moved by an offset and written in full double precision: the
// files of tests on meshes far from the origin (tests/mesh/mesh_io_test.cpp,
// tests/scene/origin_test.cpp).
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "common/mesh/mesh.hpp"

namespace plumbago::testing {

inline const std::vector<std::string>& text_mesh_formats() {
  static const std::vector<std::string> formats = {"obj", "off", "ply", "stl"};
  return formats;
}

// `mesh` in `format` ("obj", "off", "ply", "stl"), every coordinate plus `offset`.
inline std::string mesh_text_at(const Mesh& mesh, const std::string& format, double offset) {
  std::ostringstream s;
  s.precision(17);
  auto point = [&](unsigned v) {
    glm::dvec3 p = glm::dvec3(mesh.positions[v]) + offset;
    s << p.x << ' ' << p.y << ' ' << p.z;
  };
  const size_t nv = mesh.positions.size(), nf = mesh.triangles.size();
  if (format == "obj") {
    for (unsigned v = 0; v < nv; ++v) s << "v ", point(v), s << '\n';
    for (const auto& t : mesh.triangles) s << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  } else if (format == "off") {
    s << "OFF\n" << nv << ' ' << nf << " 0\n";
    for (unsigned v = 0; v < nv; ++v) point(v), s << '\n';
    for (const auto& t : mesh.triangles) s << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  } else if (format == "ply") {
    s << "ply\nformat ascii 1.0\nelement vertex " << nv
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << nf
      << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (unsigned v = 0; v < nv; ++v) point(v), s << '\n';
    for (const auto& t : mesh.triangles) s << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  } else {  // ASCII STL: every facet's corners (binary STL holds float32 only)
    s << "solid far\n";
    for (const auto& t : mesh.triangles) {
      s << "facet normal 0 0 0\nouter loop\n";
      for (int k = 0; k < 3; ++k) s << "vertex ", point(t[k]), s << '\n';
      s << "endloop\nendfacet\n";
    }
    s << "endsolid far\n";
  }
  return s.str();
}

}  // namespace plumbago::testing
