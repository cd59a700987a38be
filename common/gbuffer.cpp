#include "common/gbuffer.hpp"

#include "common/interior.hpp"

namespace plumbago {

namespace {

glm::vec3 unit_or_z(glm::vec3 v) {
  float len = glm::length(v);
  return len > 0 && std::isfinite(len) ? v / len : glm::vec3(0, 0, 1);
}

WorldObject world_object(const SceneObject& obj, const std::vector<Light>& lights, const InteriorParams& ip) {
  const Mesh& m = *obj.mesh;
  WorldObject w;
  w.flat = obj.flat;
  glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(obj.transform)));
  w.positions.reserve(m.positions.size());
  for (const auto& p : m.positions) w.positions.push_back(glm::vec3(obj.transform * glm::vec4(p, 1.0f)));
  w.normals.reserve(m.normals.size());
  for (const auto& n : m.normals) w.normals.push_back(unit_or_z(normal_matrix * n));
  w.triangles = m.triangles;
  w.gouraud.reserve(w.normals.size());
  for (const auto& n : w.normals) w.gouraud.push_back(lambert_intensity(n, lights, ip));
  return w;
}

}  // namespace

std::vector<WorldObject> world_geometry(const Scene& scene) {
  InteriorParams ip = scene.params.get<InteriorParams>();
  std::vector<WorldObject> out;
  for (const auto& obj : scene.objects) out.push_back(world_object(obj, scene.lights, ip));
  return out;
}

Image normalized_depth(const GBuffer& g) {
  Image z(g.depth.width, g.depth.height, 1);
  for (size_t i = 0; i < z.pixels(); ++i) z.data[i] = (g.depth.data[i] - g.near) / (g.far - g.near);
  return z;
}

}  // namespace plumbago
