#include "common/scene/lights.hpp"

#include <algorithm>

namespace plumbago {

float light_sum(glm::vec3 n, const std::vector<Light>& lights) {
  float sum = 0;
  for (const Light& l : lights) sum += l.intensity * std::max(0.0f, glm::dot(n, l.direction));
  return sum;
}

std::vector<Light> unit_world_lights(const Scene& scene) {
  std::vector<Light> out;
  for (const Light& l : scene.lights) out.push_back({glm::normalize(l.direction), l.intensity});
  return out;
}

std::vector<Light> view_space_lights(const Scene& scene) {
  glm::mat3 rotation(scene.camera.view());
  std::vector<Light> out;
  for (const Light& l : scene.lights) out.push_back({glm::normalize(rotation * l.direction), l.intensity});
  return out;
}

}  // namespace plumbago
