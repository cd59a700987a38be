// Composition on the GPU (SPEC 2.11), the twin of reference/compose.cpp.
#pragma once

#include "common/compose.hpp"
#include "gpu/framebuffer.hpp"

namespace plumbago::gpu {

class ComposePass {
 public:
  ComposePass();
  // Writes the RGB(A) frame into `out`. `interior_darkness` and `paper_color` are read
  // only when the flags say they exist. The shader runs only inside `inside`, where D_c or
  // D_i can differ from 0; outside it the frame is the blank page (D_c = D_i = 0), which
  // the shader draws once per size and paper and a copy puts in place every frame.
  void run(const Texture& contour_darkness, bool has_contours, const Texture& interior_darkness, bool has_interior,
           const Texture& paper_color, bool has_paper, const ComposeParams& p, Texture& out, const PixelRect& inside);

 private:
  void set_uniforms(bool has_contours, bool has_interior, bool has_paper, const ComposeParams& p);
  const Texture& blank_page(const Texture& paper_color, bool has_paper, const ComposeParams& p, const Texture& out);
  Program program_;
  FullscreenPass pass_;
  Texture page_;
  GLuint page_paper_ = 0;  // the paper texture page_ was drawn with, 0 for none
};

}  // namespace plumbago::gpu
