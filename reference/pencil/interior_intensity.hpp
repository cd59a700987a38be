// Interior intensity and brightness, CPU reference (Lee et al. 2006, §3, §5.2).
#pragma once

#include "common/pencil/interior_intensity.hpp"
#include "common/scene/gbuffer.hpp"
#include "common/scene/lights.hpp"

namespace plumbago::reference {

// I' per pixel (1 channel): Gouraud (the G-buffer's interpolated per-vertex intensity)
// or Phong (the same Lambert formula on the pixel's view-space normal), then sqrt when
// brightness_sqrt. Background: 1.
Image interior_intensity(const GBuffer& g, const std::vector<Light>& view_lights, const InteriorParams& p);

}  // namespace plumbago::reference
