#include "reference/pencil/interior_intensity.hpp"

#include "common/scene/lights.hpp"
#include "reference/core/stage.hpp"

namespace plumbago::reference {

namespace {

float pixel_intensity(const GBuffer& g, int x, int y, const std::vector<Light>& lights, const InteriorParams& p) {
  if (p.shading == InteriorShading::Gouraud) return g.gouraud.at(x, y);
  glm::vec3 n(g.normal.at(x, y, 0), g.normal.at(x, y, 1), g.normal.at(x, y, 2));
  return lambert_intensity(n, lights, p);
}

}  // namespace

Image interior_intensity(const GBuffer& g, const std::vector<Light>& view_lights, const InteriorParams& p) {
  Image out(g.depth.width, g.depth.height, 1, 1.0f);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      if (!g.background(x, y)) out.at(x, y) = adjusted_brightness(pixel_intensity(g, x, y, view_lights, p), p);
  return out;
}

PLUMBAGO_REFERENCE_STAGE(interior_intensity, [](ReferenceFrame& f) {
  f.put(kIntensity, interior_intensity(f.get(kGBuffer), view_space_lights(f.scene), f.params<InteriorParams>()));
});

}  // namespace plumbago::reference
