// Edge detection on the GPU (SPEC 2.2), the twin of reference/edge_detect.cpp.
#pragma once

#include "common/edge_detect.hpp"
#include "gpu/framebuffer.hpp"
#include "gpu/gbuffer.hpp"

namespace plumbago::gpu {

class EdgeDetectPass {
 public:
  EdgeDetectPass();
  // Writes contour darkness into `out` (R32F, the G-buffer's size).
  void run(const GBufferTargets& g, const EdgeDetectParams& p, Texture& out);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
