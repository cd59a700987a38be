#include "common/interior.hpp"

#include "common/lights.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {

float lambert_intensity(glm::vec3 n, const std::vector<Light>& unit_lights, const InteriorParams& p) {
  return std::clamp(p.ambient + p.diffuse * light_sum(n, unit_lights), 0.0f, 1.0f);
}

glm::vec3 blend_weights(glm::vec3 w, const InteriorParams& p) {
  if (p.blend == InteriorBlend::ThreeWay) return w;
  if (w.x >= w.y && w.x >= w.z) return {1, 0, 0};
  return w.y >= w.z ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
}

float adjusted_brightness(float intensity, const InteriorParams& p) {
  return p.brightness_sqrt ? std::sqrt(intensity) : intensity;
}

}  // namespace plumbago
