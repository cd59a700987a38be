// Multiple contour drawing on the GPU (SPEC 2.4), the twin of reference/multi_contour.cpp.
#pragma once

#include "common/distortion.hpp"
#include "gpu/framebuffer.hpp"

namespace plumbago::gpu {

// The per-frame-constant inputs, uploaded once: the copies' offset grids (a 2D array
// texture), the contour texture and its per-copy shifts, and the grids' largest offset.
struct ContourInputs {
  Texture offset_grids, contour_texture;
  std::vector<glm::vec2> shifts;
  float largest_offset = 0;
};
ContourInputs upload_contour_inputs(const std::vector<Image>& grids, const Image& contour_texture,
                                    std::vector<glm::vec2> shifts);

class MultiContourPass {
 public:
  MultiContourPass();
  // `lit` must be sampled LINEAR/CLAMP_TO_EDGE (set here); writes D_c into `out` (R32F).
  // Only `covered` (common/distortion.hpp contour_rect) runs the shader; outside it D_c = 0.
  // Inside it, pixels whose copies can only read d' = 0 (found from the largest d' of each
  // block of pixels, contour_blocks.frag) are not shaded either: their D_c is 0 too.
  void run(const Texture& lit, const ContourInputs& in, const ContourParams& p, Texture& out, const PixelRect& covered);

 private:
  Program program_, blocks_program_;
  FullscreenPass pass_;
  Texture block_max_;
};

}  // namespace plumbago::gpu
