// Interior intensity (SPEC 2.5) and interior pencil shading (SPEC 2.6-2.10) on the GPU in
// one pass with two outputs, the twins of reference/interior_intensity.cpp and
// reference/pencil_interior.cpp.
#pragma once

#include "common/interior.hpp"
#include "common/pencil_interior.hpp"
#include "gpu/framebuffer.hpp"
#include "gpu/gbuffer.hpp"

namespace plumbago::gpu {

class PencilInteriorPass {
 public:
  PencilInteriorPass();
  // `stack`: the pencil layers as a 3D texture; `paper_normal`: any texture when
  // !options.paper. Writes D_i into `darkness` and, if given, I' into `intensity` (R32F;
  // a frame leaves it out: only a dump reads it). Only `covered` (common/scene.hpp
  // filter_rect, radius 0) runs the shader; outside it the background's D_i = 0 and I' = 1.
  void run(const GBufferTargets& g, const TriangleAngles& angles, const std::vector<Light>& view_lights, const Texture& stack,
           const Texture& paper_normal, const InteriorOptions& options, const InteriorParams& p, float mu_p,
           Texture& darkness, Texture* intensity, const PixelRect& covered);

 private:
  const Program& program_for(const InteriorOptions& options, const InteriorParams& p, bool writes_intensity);
  ProgramVariants programs_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
