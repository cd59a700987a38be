// Interior pencil shading on the GPU (SPEC 2.6-2.10), the twin of
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
  // !options.paper. Writes D_i into `out` (R32F).
  void run(const GBufferTargets& g, const Texture& intensity, const Texture& stack, const Texture& paper_normal,
           const InteriorOptions& options, const InteriorParams& p, float mu_p, Texture& out);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
