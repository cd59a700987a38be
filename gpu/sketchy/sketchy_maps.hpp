// Sketchy drawing's maps on the GPU (Nienhaus & Döllner 2004, §3.1), the twin of reference/sketchy/sketchy_maps.cpp.
#pragma once

#include <vector>

#include "common/pencil/edge_detect.hpp"
#include "gpu/gl/framebuffer.hpp"
#include "gpu/scene/gbuffer.hpp"

namespace plumbago::gpu {

class SketchyMapsPass {
 public:
  // `colors`: one unlit color per object of the G-buffer's scene.
  explicit SketchyMapsPass(const std::vector<glm::vec3>& colors);
  // `edge` (RG32F): contour darkness and the depth it belongs to; `shade` (RGBA8). Only
  // `covered` (common/scene/scene.hpp filter_rect, radius 1) runs the shader; outside it the
  // maps get the background's values.
  void run(const GBufferTargets& g, const EdgeDetectParams& p, Texture& edge, Texture& shade, const PixelRect& covered);

 private:
  Program program_;
  FullscreenPass pass_;
  Texture colors_;
};

}  // namespace plumbago::gpu
