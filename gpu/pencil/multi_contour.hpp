// Multiple contour drawing on the GPU (Lee et al. 2006, §4.2-4.3), the twin of reference/pencil/multi_contour.cpp.
#pragma once

#include <string>

#include "common/pencil/distortion.hpp"
#include "common/pencil/multi_contour.hpp"
#include "gpu/gl/framebuffer.hpp"
#include "gpu/pencil/contour_blocks.hpp"

namespace plumbago::gpu {

// What the copies read that does not change from frame to frame, made once per window
// size and parameters from the copies' offset grids, the contour texture and its shifts:
// per pixel and copy, the offset and the texture factor (contour_copies.frag); and the
// grids' largest offset.
struct ContourInputs {
  Texture copy_inputs;  // GL_TEXTURE_2D_ARRAY, RGBA32F, one layer per copy
  float largest_offset = 0;
};
ContourInputs make_contour_inputs(const ContourParams& p, const std::vector<Image>& grids, const Image& contour_texture,
                                  const std::vector<glm::vec2>& shifts, int width, int height);
// The same from a frame's preprocessing (gpu/core/stage.hpp).
class GpuFrame;
ContourInputs make_contour_inputs(const GpuFrame& f);

// What drawing the contours reads in a frame, for a pass that draws them itself
// (compose.frag with MULTI_CONTOUR on, shaders/pencil/common_multi_contour.glsl).
struct ContourSources {
  const Texture& lit;              // d', LINEAR/CLAMP_TO_EDGE
  const Texture& copy_inputs;      // ContourInputs::copy_inputs
  const Texture& block_reach_max;  // contour_block_reach.frag
  ContourParams params;
};
// The prelude of a program that includes shaders/pencil/common_multi_contour.glsl.
std::string multi_contour_prelude();

class MultiContourPass {
 public:
  MultiContourPass();
  // `lit` must be sampled LINEAR/CLAMP_TO_EDGE (set here); writes D_c into `out` (R32F).
  // `in` was made with `p` at lit's size.
  // Only `covered` (common/pencil/distortion.hpp contour_rect) runs the shader; outside it D_c = 0.
  // Inside it, blocks of pixels whose copies can only read d' = 0 (found from the blocks'
  // marks, mark_blocks, and the marks within the copies' reach, contour_block_reach.frag)
  // are not shaded either: their D_c is 0 too. A frame draws the contours in the
  // composition pass (prepare); this pass runs for parity, or a frame that draws contours
  // without composing them.
  void run(const Texture& lit, const ContourInputs& in, const ContourParams& p, Texture& out, const PixelRect& covered);
  // The same checks and block passes, without the drawing: what another pass needs to draw
  // the contours (valid until the next call). `marks`: the blocks' marks made while d' was
  // drawn (gpu/pencil/edge_detect.hpp), or null to find them here from d'.
  ContourSources prepare(const Texture& lit, const ContourInputs& in, const ContourParams& p,
                         const Texture* marks = nullptr);
  // Marks the blocks of `lit` that hold some d' > 0 (contour_blocks.frag) into `marks`
  // (make_contour_block_marks of lit's size). A frame's edge pass marks them as it draws
  // d'; this is for d' uploaded by parity (tests/pencil/skipped_pixels_test.cpp checks the two agree).
  void mark_blocks(const Texture& lit, Texture& marks);

 private:
  Program program_, blocks_program_, reach_program_;
  FullscreenPass pass_;
  Texture block_marks_, block_reach_max_;
};

}  // namespace plumbago::gpu
