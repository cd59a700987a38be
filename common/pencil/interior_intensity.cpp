#include "common/pencil/interior_intensity.hpp"

#include "common/scene/lights.hpp"

#include <algorithm>
#include <cmath>

namespace plumbago {

float lambert_intensity(glm::vec3 n, const std::vector<Light>& unit_lights, const InteriorParams& p) {
  return std::clamp(p.ambient + p.diffuse * light_sum(n, unit_lights), 0.0f, 1.0f);
}

float adjusted_brightness(float intensity, const InteriorParams& p) {
  return p.brightness_sqrt ? std::sqrt(intensity) : intensity;
}

}  // namespace plumbago
