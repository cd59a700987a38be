#include "common/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {

glm::vec3 Mesh::bbox_min() const {
  glm::vec3 lo(INFINITY);
  for (const auto& p : positions) lo = glm::min(lo, p);
  return positions.empty() ? glm::vec3(0) : lo;
}

glm::vec3 Mesh::bbox_max() const {
  glm::vec3 hi(-INFINITY);
  for (const auto& p : positions) hi = glm::max(hi, p);
  return positions.empty() ? glm::vec3(0) : hi;
}

float Mesh::bbox_diagonal() const { return glm::length(bbox_max() - bbox_min()); }

void compute_normals(Mesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0));
  for (const auto& t : mesh.triangles) {
    glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    glm::dvec3 area_normal = glm::cross(b - a, c - a);  // length = 2 x area
    for (int k = 0; k < 3; ++k) sum[t[k]] += area_normal;
  }
  mesh.normals.resize(mesh.positions.size());
  for (size_t i = 0; i < sum.size(); ++i) {
    double len = glm::length(sum[i]);
    mesh.normals[i] = len > 0 && std::isfinite(len) ? glm::vec3(sum[i] / len) : glm::vec3(0, 0, 1);
  }
}

}  // namespace plumbago
