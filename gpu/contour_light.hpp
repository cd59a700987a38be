// Contour lighting on the GPU (SPEC 2.3), the twin of reference/contour_light.cpp.
#pragma once

#include "common/contour_light.hpp"
#include "gpu/framebuffer.hpp"
#include "gpu/gbuffer.hpp"

namespace plumbago::gpu {

class ContourLightPass {
 public:
  ContourLightPass();
  // Writes the lit contour darkness d' into `out` (R32F).
  void run(const Texture& contour_darkness, const GBufferTargets& g, const std::vector<Light>& view_lights,
           const ContourLightParams& p, Texture& out);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
