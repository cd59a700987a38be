// Multiple contour drawing on the GPU (SPEC 2.4), the twin of reference/multi_contour.cpp.
#pragma once

#include "common/distortion.hpp"
#include "gpu/framebuffer.hpp"

namespace plumbago::gpu {

// The per-frame-constant inputs, uploaded once: the copies' offset grids (a 2D array
// texture), the contour texture and its per-copy shifts.
struct ContourInputs {
  Texture offset_grids, contour_texture;
  std::vector<glm::vec2> shifts;
};
ContourInputs upload_contour_inputs(const std::vector<Image>& grids, const Image& contour_texture,
                                    std::vector<glm::vec2> shifts);

class MultiContourPass {
 public:
  MultiContourPass();
  // `lit` must be sampled LINEAR/CLAMP_TO_EDGE (set here); writes D_c into `out` (R32F).
  // Only `covered` (common/distortion.hpp contour_rect) runs the shader; outside it D_c = 0.
  void run(const Texture& lit, const ContourInputs& in, const ContourParams& p, Texture& out, const PixelRect& covered);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
