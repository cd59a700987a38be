#include "common/strokes/silhouette_segments.hpp"

#include "common/scene/scene.hpp"

namespace plumbago {

std::vector<uint32_t> first_records(const Scene& scene) {
  std::vector<uint32_t> first{0};
  for (const SceneObject& o : scene.objects) first.push_back(first.back() + uint32_t(o.mesh->triangles.size()));
  return first;
}

}  // namespace plumbago
