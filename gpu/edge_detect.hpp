// Edge detection (SPEC 2.2) and contour lighting (SPEC 2.3) on the GPU in one pass, the
// twins of reference/edge_detect.cpp and reference/contour_light.cpp: one fragment
// shader, two outputs, so both stages stay testable and the frame reads the G-buffer once.
#pragma once

#include "common/contour_light.hpp"
#include "common/edge_detect.hpp"
#include "gpu/framebuffer.hpp"
#include "gpu/gbuffer.hpp"

namespace plumbago::gpu {

class EdgeDetectPass {
 public:
  EdgeDetectPass();
  // Writes contour darkness d into `darkness` and the lit d' into `lit` (R32F, the
  // G-buffer's size). Only `covered` (common/scene.hpp filter_rect, radius 1) runs the
  // shader; outside it both get the background's d.
  void run(const GBufferTargets& g, const EdgeDetectParams& p, const std::vector<Light>& view_lights,
           const ContourLightParams& light, Texture& darkness, Texture& lit, const PixelRect& covered);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
