#include "reference/pencil/contour_light.hpp"

#include <algorithm>

#include "common/scene/lights.hpp"
#include "reference/core/stage.hpp"

namespace plumbago::reference {

namespace {

// l_c = 1 - lambda min(1, sum intensity max(0, N.L))  (Lee Eq. 1)
float contour_light_factor(glm::vec3 n, const std::vector<Light>& lights, const ContourLightParams& p) {
  return 1.0f - p.light_influence * std::min(1.0f, light_sum(n, lights));
}

}  // namespace

Image lit_contour_darkness(const Image& d, const GBuffer& g, const std::vector<Light>& view_lights,
                           const ContourLightParams& p) {
  Image out(d.width, d.height, 1);
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) {
      glm::vec3 n(g.normal.at(x, y, 0), g.normal.at(x, y, 1), g.normal.at(x, y, 2));
      out.at(x, y) = d.at(x, y) * contour_light_factor(n, view_lights, p);
    }
  return out;
}

PLUMBAGO_REFERENCE_STAGE(contour_light, [](ReferenceFrame& f) {
  f.put(kLitContourDarkness, lit_contour_darkness(f.get(kContourDarkness), f.get(kGBuffer), view_space_lights(f.scene),
                                                  f.params<ContourLightParams>()));
});

}  // namespace plumbago::reference
