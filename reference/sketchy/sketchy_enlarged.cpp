#include "reference/sketchy/sketchy_enlarged.hpp"
#include "common/sketchy/sketchy_enlarged.hpp"

#include "common/sketchy/sketchy.hpp"
#include "reference/core/stage.hpp"
#include "reference/scene/gbuffer.hpp"
#include "reference/util/rows.hpp"

namespace plumbago::reference {

Image enlarged_noise_coordinates(const Scene& enlarged, int width, int height) {
  GBuffer g = trace_gbuffer(enlarged, width, height);
  std::vector<std::vector<glm::vec3>> coords;
  for (const SceneObject& o : enlarged.objects) coords.push_back(noise_coordinates(*o.mesh));
  Image out(width, height, 4);
  for_each_row(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      uint32_t id = g.ids.at(x, y, 0);
      if (id == 0) continue;
      const glm::uvec3& tri = enlarged.objects[id - 1].mesh->triangles[g.ids.at(x, y, 1)];
      glm::vec3 q(0.0f);
      for (int k = 0; k < 3; ++k) q += g.bary.at(x, y, k) * coords[id - 1][tri[k]];
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = q[c];
      out.at(x, y, 3) = 1.0f;
    }
  });
  return out;
}

PLUMBAGO_REFERENCE_STAGE(sketchy_enlarged, [](ReferenceFrame& f) {
  f.put(kNoiseCoordinates, enlarged_noise_coordinates(enlarged_scene(f.sketchy), f.scene.width, f.scene.height));
});

}  // namespace plumbago::reference
