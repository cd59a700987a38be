// Contour lighting, CPU reference (Lee et al. 2006, §4.1, Eq. 1).
#pragma once

#include <vector>

#include "common/pencil/contour_light.hpp"
#include "common/scene/gbuffer.hpp"

namespace plumbago::reference {

// Lit contour darkness d' = d l_c (1 channel).
Image lit_contour_darkness(const Image& contour_darkness, const GBuffer& g, const std::vector<Light>& view_lights,
                           const ContourLightParams& p);

}  // namespace plumbago::reference
