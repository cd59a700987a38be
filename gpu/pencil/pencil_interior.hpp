// Interior intensity (Lee et al. 2006, §3, §5.2) and interior pencil shading (Lee et al. 2006, §5.1-5.5) on the GPU in
// one pass with two outputs, the twins of reference/pencil/interior_intensity.cpp and
// reference/pencil/pencil_interior.cpp.
#pragma once

#include "common/pencil/interior_intensity.hpp"
#include "common/pencil/pencil_interior.hpp"
#include "gpu/gl/framebuffer.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago::gpu {

// What the interior reads: the G-buffer (normals, barycentrics, ids) and its corner angles,
// the pencil layers as a 3D texture and the paper's normal map (any texture when
// !options.paper).
struct PencilInteriorInputs {
  const GBufferTargets& gbuffer;
  const TriangleAngles& angles;
  const std::vector<Light>& view_lights;
  const Texture& stack;
  const Texture& paper_normal;
  InteriorOptions options;
};

// D_i (R32F) and, if wanted, I' (R32F; a frame leaves it out: only a dump reads it).
struct PencilInteriorOutputs {
  Texture& darkness;
  Texture* intensity = nullptr;
};

class PencilInteriorPass {
 public:
  PencilInteriorPass();
  // Only `covered` (common/scene/scene.hpp filter_rect, radius 0) runs the shader; outside it
  // the background's D_i = 0 and I' = 1.
  void run(const PencilInteriorInputs& in, const InteriorParams& p, float mu_p, const PencilInteriorOutputs& out,
           const PixelRect& covered);

 private:
  const Program& program_for(const InteriorOptions& options, const InteriorParams& p, bool writes_intensity);
  ProgramVariants programs_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
