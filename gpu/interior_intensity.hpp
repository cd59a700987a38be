// Interior intensity and brightness on the GPU (SPEC 2.5), the twin of
// reference/interior_intensity.cpp.
#pragma once

#include "common/interior.hpp"
#include "gpu/framebuffer.hpp"
#include "gpu/gbuffer.hpp"

namespace plumbago::gpu {

class InteriorIntensityPass {
 public:
  InteriorIntensityPass();
  // Writes I' into `out` (R32F).
  void run(const GBufferTargets& g, const std::vector<Light>& view_lights, const InteriorParams& p, Texture& out);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
