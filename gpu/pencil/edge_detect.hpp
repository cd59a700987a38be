// Edge detection (Nienhaus & Döllner 2003, as given in Pacheco §2) and contour lighting (Lee et al. 2006, §4.1, Eq. 1)
// on the GPU in one pass, the twins of reference/pencil/edge_detect.cpp and reference/pencil/contour_light.cpp: one
// fragment shader, two outputs, so both stages stay testable and the frame reads the G-buffer once.
#pragma once

#include "common/pencil/contour_light.hpp"
#include "common/pencil/edge_detect.hpp"
#include "gpu/gl/framebuffer.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago::gpu {

// What the pass writes: the lit d' (R32F, the G-buffer's size), and if wanted the unlit d
// (the same; a frame reads only d') and the marks of the blocks of pixels where d' > 0
// (gpu/pencil/multi_contour.hpp make_contour_block_marks: a frame's multiple contours skip the others).
struct EdgeOutputs {
  Texture& lit;
  Texture* darkness = nullptr;
  Texture* block_marks = nullptr;
};

class EdgeDetectPass {
 public:
  EdgeDetectPass();
  // Only `covered` (common/scene/scene.hpp filter_rect, radius 1) runs the shader; outside it d
  // and d' are the background's d, and the blocks' marks say so.
  void run(const GBufferTargets& g, const EdgeDetectParams& p, const std::vector<Light>& view_lights,
           const ContourLightParams& light, const EdgeOutputs& out, const PixelRect& covered);

 private:
  ProgramVariants programs_;  // with d written or not, blocks marked or not
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
