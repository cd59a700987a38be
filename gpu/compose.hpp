// Composition on the GPU (SPEC 2.11), the twin of reference/compose.cpp.
#pragma once

#include "common/compose.hpp"
#include "gpu/framebuffer.hpp"

namespace plumbago::gpu {

class ComposePass {
 public:
  ComposePass();
  // Writes the RGB(A) frame into `out` from contour darkness.
  void run(const Texture& contour_darkness, const ComposeParams& p, Texture& out);

 private:
  Program program_;
  FullscreenPass pass_;
};

}  // namespace plumbago::gpu
