#include "common/interior.hpp"

#include <algorithm>

namespace plumbago {

float lambert_intensity(glm::vec3 n, const std::vector<Light>& lights, const InteriorParams& p) {
  float sum = 0;
  for (const Light& l : lights) sum += l.intensity * std::max(0.0f, glm::dot(n, glm::normalize(l.direction)));
  return std::clamp(p.ambient + p.diffuse * sum, 0.0f, 1.0f);
}

}  // namespace plumbago
