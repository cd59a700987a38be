// Composition on the GPU (SPEC 2.11), the twin of reference/compose.cpp.
#pragma once

#include "common/compose.hpp"
#include "gpu/framebuffer.hpp"

namespace plumbago::gpu {

class ComposePass {
 public:
  ComposePass();
  // Writes the RGB(A) frame into `out`. `interior_darkness` and `paper_color` are read
  // only when the flags say they exist.
  void run(const Texture& contour_darkness, bool has_contours, const Texture& interior_darkness, bool has_interior,
           const Texture& paper_color, bool has_paper, const ComposeParams& p, Texture& out);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
