#include "common/pencil/pencil_interior.hpp"

namespace plumbago {

glm::vec3 blend_weights(glm::vec3 w, const InteriorParams& p) {
  if (p.blend == InteriorBlend::ThreeWay) return w;
  if (w.x >= w.y && w.x >= w.z) return {1, 0, 0};
  return w.y >= w.z ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
}

}  // namespace plumbago
