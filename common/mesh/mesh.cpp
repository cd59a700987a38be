#include "common/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

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
  std::vector<glm::vec2> uvs;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::uvec3& t = mesh.triangles[f];
    glm::uvec3 r(remap[t[0]], remap[t[1]], remap[t[2]]);
    if (r[0] == r[1] || r[1] == r[2] || r[0] == r[2]) continue;
    faces.push_back(r);
    if (!mesh.uvs.empty()) uvs.insert(uvs.end(), &mesh.uvs[3 * f], &mesh.uvs[3 * f] + 3);
  }
  size_t merged = mesh.positions.size() - kept.size();
  mesh.positions = std::move(kept);
  mesh.triangles = std::move(faces);
  mesh.uvs = std::move(uvs);
  return merged;
}

}  // namespace plumbago
