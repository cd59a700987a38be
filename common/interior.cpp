#include "common/interior.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {

float lambert_intensity(glm::vec3 n, const std::vector<Light>& lights, const InteriorParams& p) {
  float sum = 0;
  for (const Light& l : lights) sum += l.intensity * std::max(0.0f, glm::dot(n, glm::normalize(l.direction)));
  return std::clamp(p.ambient + p.diffuse * sum, 0.0f, 1.0f);
}

std::vector<Light> view_space_lights(const Scene& scene) {
  glm::mat3 rotation(scene.camera.view());
  std::vector<Light> out;
  for (const Light& l : scene.lights) out.push_back({glm::normalize(rotation * l.direction), l.intensity});
  return out;
}

float adjusted_brightness(float intensity, const InteriorParams& p) {
  return p.brightness_sqrt ? std::sqrt(intensity) : intensity;
}

}  // namespace plumbago
